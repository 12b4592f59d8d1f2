#pragma once
// The words of `penumbra --help` and `penumbra grid --help`: what the numbers mean, in which
// units, and a command line to copy.

namespace penumbra::help {

inline constexpr const char* kProgram =
    "penumbra computes the exact direct illuminance E, in lux (lx), that area light sources "
    "(luminaires, windows; Lambertian, luminance in cd/m2) give at the points of calculation "
    "grids, with exact shadows and penumbrae from convex solids (walls, slabs, furniture).\n"
    "Scenes are YAML files in metres (format: docs/scene-format.md).";

inline constexpr const char* kProgramFooter =
    "Examples:\n"
    "  penumbra grid data/office.yaml -o out/office    illuminance on every grid of the scene\n"
    "  penumbra devices                                the OpenCL devices --device can name\n"
    "  penumbra grid --help                            the outputs and their units";

inline constexpr const char* kGrid =
    "Compute E (lx) at every point of the scene's calculation grids and write the results to "
    "the output directory.";

inline constexpr const char* kGridFooter =
    "Outputs (in the directory given with -o):\n"
    "  <grid>.csv    one row per point, header x_m,y_m,z_m,nx,ny,nz,E_lx,inside:\n"
    "                position (m), unit normal of the receiving surface, illuminance (lx), and\n"
    "                the name of the solid the point lies inside (empty when none)\n"
    "  <grid>.res    E in lx, one value a line, in point order (the order of Radiance's rtrace)\n"
    "  summary.json  scene, device, timing (s) and per grid: points, points_inside_solids,\n"
    "                spacing_m, Eavg_lx, Emin_lx, Emax_lx, U0 = Emin/Eavg, Ud = Emin/Emax, time_s\n"
    "A table of the same metrics is printed at the end.\n"
    "\n"
    "Points inside a solid get E = 0 and are left out of Eavg, Emin, Emax, U0 and Ud.\n"
    "The files appear together when the run has succeeded, never half-written. If the\n"
    "directory exists, only the files named above are replaced; other files stay.\n"
    "\n"
    "The default estimator is the exact OpenCL kernel (Lambert's contour integral over the\n"
    "visible part of each source). --reference uses an independent check instead: about\n"
    "n*n sample points on each source face (a Fibonacci lattice) with exact ray-solid tests\n"
    "on the host, in double precision; its error falls about as 1/n^2, its time grows as n^2.\n"
    "\n"
    "Examples:\n"
    "  penumbra grid data/office.yaml -o out/office\n"
    "  penumbra grid data/office.yaml -o out/desk --grid desk-1-top --reference\n"
    "\n"
    "Exit status: 0 done; 1 error (device, output directory, options); 2 invalid scene, reported\n"
    "as file:line: key: message. Nothing is written unless the run succeeds.";

inline constexpr const char* kDevices =
    "List the OpenCL devices: index (what --device takes), type, name, platform, compute units.";

}  // namespace penumbra::help
