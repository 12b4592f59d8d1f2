#pragma once
// The words of `penumbra plot --help` and of the plot options of `penumbra grid`.

namespace penumbra::viz::help {

inline constexpr const char* kPlot =
    "Draw the results of a `penumbra grid` run (or the UGR maps of a `penumbra glare` run): a "
    "heat map with isolux lines per planar grid, "
    "the room's surfaces in false colour, and the data as VTK files for ParaView. Illuminance E "
    "in lux (lx), lengths in metres (m).";

inline constexpr const char* kPlotFlag =
    "After a successful run, plot the output directory as `penumbra plot` does (the plot options "
    "below apply)";

inline constexpr const char* kPlotFooter =
    "Outputs (in FOLDER, beside the grid results):\n"
    "  <grid>.png    per planar grid: E in false colour over the calculation area (bilinear\n"
    "                between the points), isolux lines labelled in lx, the room outline and the\n"
    "                solids the grid's plane cuts, Emax (circle) and Emin (square) marked, and\n"
    "                Eavg, Emin, Emax, U0 = Emin/Eavg, Ud = Emin/Emax in the title\n"
    "  <grid>.vti    per planar grid, for ParaView: the lattice with point arrays E_lx (the\n"
    "                CSV's values exactly), Normals and inside_solid; a point list gives "
    "<grid>.vtp\n"
    "  surfaces.vtp  every face of every solid, sampled about --surface-spacing apart: E_lx,\n"
    "                L_cd_m2 (L = rho*E/pi, rho the luminance Y of the material's reflectance;\n"
    "                NaN without a material), Normals; cells carry the solid and face index\n"
    "  surfaces.png  the room seen from above one corner, in false colour; the ceiling and the\n"
    "                two walls nearest the camera are left out of the picture (not of the file)\n"
    "  <grid>-df.png per planar grid of a scene with a sky: the daylight factor DF in %\n"
    "                (100 E/E_h, E_h the sky's horizontal illuminance outdoors), the EN 17037\n"
    "                targets D_T as isolines where the site gives its median diffuse\n"
    "                illuminance (else DF 1, 2, 3 and 5 %), DFavg, DFmedian, DFmin, U0 and the\n"
    "                EN 17037 level in the title\n"
    "  <entry>-ugr.png  on the folder of `penumbra glare`, per observer grid: each eye's UGR_max\n"
    "                (CIE 117, over its lines of sight) in false colour, UGR [-], the EN 12464-1\n"
    "                limit --ugr-limit (default 19) as an isoline\n"
    "\n"
    "Legend: linear from 0 lx to a round value at or above Emax; --range fixes it, so that\n"
    "variants plotted with the same range compare colour for colour; --log makes it\n"
    "logarithmic. The surfaces' automatic range ends at a round value above the 98th\n"
    "percentile of E, so that a bright spot by a window does not darken the whole room.\n"
    "Values beyond the range take the end colours.\n"
    "Isolux lines: the 1-2-5 series between Emin and Emax (100, 200, 500, 1000 lx ...), or\n"
    "multiples of a round step when that gives fewer than three lines; --isolux sets them.\n"
    "\n"
    "The scene is read again from the path in summary.json; E on the room's surfaces is\n"
    "computed on the OpenCL device (--device). The pictures are rendered through X: where\n"
    "there is no display, run penumbra under a virtual one:\n"
    "  xvfb-run -a -s \"-screen 0 1920x1080x24 -noreset\" penumbra plot out/office\n"
    "The files appear together when all are done, never half-written.\n"
    "\n"
    "Examples:\n"
    "  penumbra plot out/office\n"
    "  penumbra plot out/variant-b --range 0:1500 --isolux 300,500,750,1000\n"
    "  penumbra grid data/office.yaml -o out/office --plot --palette falsecolor\n"
    "\n"
    "Exit status: 0 done; 1 error (no display, results missing or malformed, device, options);\n"
    "2 the scene is invalid, reported as file:line: key: message.";

}  // namespace penumbra::viz::help
