#pragma once
// What a photometric file holds once read (IES LM-63 or EULUMDAT), in one form for both formats:
// the angles as the file gives them, candela after every multiplier, lengths in metres.
// docs/photometry.md describes the fields, the frames and the symmetries.
#include <optional>
#include <string>
#include <vector>

namespace penumbra::photometry {

enum class PhotometricFormat { Ies, Eulumdat };

// The angle system of the table (CIE 70, EN 13032-1, LM-63): C-γ (vertical polar axis),
// B-β (horizontal polar axis across the beam) and A-α (polar axis along the luminaire's up).
enum class PhotometricType { C, B, A };

// Which planes the file stores and how the rest of the sphere follows from them.
enum class HorizontalSymmetry {
  Rotational,    // one plane for every C: IES a single horizontal angle 0, EULUMDAT Isym 1
  Quadrant,      // C0-C90, mirrored about C0-C180 and C90-C270: IES 0-90, Isym 4
  AboutC0C180,   // C0-C180, I(C) = I(360 - C): IES 0-180, Isym 2
  AboutC90C270,  // C90-C270, I(C) = I(180 - C): IES (1995) 90-270, Isym 3
  None,          // C0-C360 (IES: last angle above 180), Isym 0; types A and B from -90
  Lateral,       // types A and B with horizontal angles 0-90: I(H) = I(-H)
};

enum class OpeningShape {
  Point,
  Rectangle,  // length (C0-C180) x width (C90-C270), horizontal
  RectangleWithLuminousSides,
  Disk,  // diameter = length = width
  Ellipse,
  VerticalCylinder,  // diameter, height
  VerticalEllipticalCylinder,
  Sphere,
  Ellipsoid,
  HorizontalCylinderAlongLength,  // axis along C0-C180
  HorizontalCylinderAlongWidth,   // axis along C90-C270
  VerticalDiskFacingLength,       // a disk in the C90-C270 vertical plane, facing C0
  VerticalDiskFacingWidth,        // a disk in the C0-C180 vertical plane, facing C90
};

// The luminous opening, in metres, extents positive whatever sign the file used.
struct LuminousOpening {
  OpeningShape shape = OpeningShape::Point;
  double lengthM = 0;  // along C0-C180 (local x)
  double widthM = 0;   // along C90-C270 (local y)
  double heightM = 0;  // along the vertical (local z)
  // EULUMDAT gives the height of the luminous area at C0, C90, C180 and C270 (m); the IES
  // opening has one height, repeated here.
  double sideHeightsM[4] = {0, 0, 0, 0};
};

// One set of lamps (EULUMDAT has one or more; an IES file one).
struct LampSet {
  int count = 1;               // negative in EULUMDAT files with absolute photometry
  std::string type;            // text as given
  double lumens = 0;           // lm, the whole set
  std::string colour;          // text as given (EULUMDAT)
  std::string renderingIndex;  // text as given (EULUMDAT)
  double watts = 0;            // W, with ballast
};

// IES TILT=INCLUDE: the lamp output factor against the luminaire's tilt.
struct TiltTable {
  int lampToLuminaireGeometry =
      1;  // 1 vertical base-up or base-down, 2 horizontal along C90, 3 along C0
  std::vector<double> anglesDeg;
  std::vector<double> factors;
};

// A keyword line of an IES file ("TEST", "MANUFAC", "_LOR": the text after the brackets) or a
// named header line of a EULUMDAT file ("luminaire name", "date/user").
struct HeaderField {
  std::string name;
  std::string value;
  int line = 0;
};

struct PhotometricData {
  PhotometricFormat format = PhotometricFormat::Ies;
  std::string version;  // "LM-63-2002", "LM-63-1986" (no version line), "EULUMDAT"
  PhotometricType type = PhotometricType::C;
  HorizontalSymmetry symmetry = HorizontalSymmetry::Rotational;
  // As the file gives them, increasing (EULUMDAT: the stored planes only). Type C: horizontal
  // = C, vertical = γ; types A and B: horizontal = H, vertical = V (docs/photometry.md).
  std::vector<double> horizontalAnglesDeg;
  std::vector<double> verticalAnglesDeg;
  // cd, horizontal-major: candela[h * verticalAnglesDeg.size() + v]; after the IES candela
  // multiplier and ballast factors, or EULUMDAT's cd/klm times the lamps' klm and the
  // conversion factor.
  std::vector<double> candela;

  std::vector<LampSet> lamps;
  double lampLumens = 0;            // lm, all lamps together (0 with IES absolute photometry)
  bool absolutePhotometry = false;  // IES lumens per lamp -1, or a EULUMDAT lamp count < 0
  std::optional<double> lightOutputRatio;  // fraction; EULUMDAT LORL / 100, IES [_LOR] / 100
  double inputWatts = 0;                   // W
  LuminousOpening opening;
  std::optional<TiltTable> tilt;  // IES TILT=INCLUDE
  std::vector<HeaderField> header;
  std::vector<std::string> warnings;  // read, but something is unusual

  double candelaAt(std::size_t horizontal, std::size_t vertical) const {
    return candela[horizontal * verticalAnglesDeg.size() + vertical];
  }
};

// Names for reports: "C", "IES LM-63", "Isym 2 (about C0-C180)" style.
std::string formatName(PhotometricFormat format);
std::string typeName(PhotometricType type);
std::string symmetryName(HorizontalSymmetry symmetry);
std::string openingShapeName(OpeningShape shape);

}  // namespace penumbra::photometry
