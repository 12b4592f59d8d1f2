#pragma once
// The words of `penumbra --help` and `penumbra grid --help`: what the numbers mean, in which
// units, and a command line to copy.

namespace penumbra::help {

inline constexpr const char* kProgram =
    "penumbra computes the illuminance E, in lux (lx), that area light sources (panels, "
    "windows; Lambertian, luminance in cd/m2) and photometric luminaires (IES, EULUMDAT) give "
    "at the points of calculation grids: the direct light exactly, with exact shadows and "
    "penumbrae from convex solids (walls, slabs, furniture), plus the light the room's "
    "surfaces reflect (radiosity with the same exact integral; faces without a material are "
    "black).\n"
    "Scenes are YAML files in metres (format: docs/scene-format.md).";

inline constexpr const char* kProgramFooter =
    "Examples:\n"
    "  penumbra grid data/office.yaml -o out/office    illuminance on every grid of the scene\n"
    "  penumbra sweep studies/window-width.yaml -o out/window-width\n"
    "                                                  every case of a parameter study, one table\n"
    "  penumbra plot out/office                        heat maps, isolux lines, room surfaces\n"
    "  penumbra devices                                the OpenCL devices --device can name\n"
    "  penumbra luminaire data/luminaires/batwing.ldt  what a photometric file (.ies, .ldt) holds\n"
    "  penumbra grid --help                            the outputs and their units";

inline constexpr const char* kGrid =
    "Compute E (lx) at every point of the scene's calculation grids and write the results to "
    "the output directory. E is the total illuminance: the direct light plus the light the "
    "room's surfaces reflect (--direct-only: the direct light alone).";

inline constexpr const char* kGridFooter =
    "Outputs (in the directory given with -o):\n"
    "  <grid>.csv    one row per point, header\n"
    "                x_m,y_m,z_m,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,inside:\n"
    "                position (m), unit normal of the receiving surface, the total illuminance\n"
    "                (lx), its direct and interreflected parts (lx), and the name of the solid\n"
    "                the point lies inside (empty when none); with --direct-only\n"
    "                x_m,y_m,z_m,nx,ny,nz,E_lx,inside\n"
    "                With a sky (daylight through the openings) the daylight factor in % follows\n"
    "                the E columns: DF_pct = 100 E / E_h (E_h the sky's outdoor horizontal\n"
    "                illuminance), and with interreflection DF_direct_pct and DF_internal_pct,\n"
    "                which add up to DF_pct\n"
    "  <grid>.res    E in lx, one value a line, in point order (the order of Radiance's rtrace)\n"
    "  summary.json  scene, its parameters' values, device, timing (s), what E includes\n"
    "                (\"illuminance\"), the interreflection solver's report (elements,\n"
    "                relative_residual, timing) and per grid: points, points_inside_solids,\n"
    "                spacing_m, Eavg_lx, Emin_lx, Emax_lx, U0 = Emin/Eavg, Ud = Emin/Emax,\n"
    "                time_s, and the same metrics of the direct part under \"direct\"\n"
    "                (and kind, columns, rows and scene_absolute, which `penumbra plot` reads);\n"
    "                with a sky, \"daylight_factor\": DFavg_pct, DFmedian_pct, DFmin_pct,\n"
    "                DFmax_pct, DF_uniformity = DFmin/DFavg, its direct and internal means and\n"
    "                the shares of the points at or above DF 1, 2, 3 and 5 %, and with the\n"
    "                site's median_diffuse_illuminance_lx \"en17037\": per level (minimum,\n"
    "                medium, high) the DF targets and the shares reaching them (%), met,\n"
    "                and level_reached\n"
    "A table of the same metrics is printed at the end. With --plot, the pictures and VTK\n"
    "files of `penumbra plot` follow (see `penumbra plot --help`).\n"
    "\n"
    "Points inside a solid get E = 0 and are left out of Eavg, Emin, Emax, U0 and Ud.\n"
    "U0 and Ud are null (\"-\" in the table) for point lists: sensors make no area.\n"
    "E and its metrics have the digits the kernels compute them with, those of a float\n"
    "(at most 9 significant; the reference estimator's double digits with --reference);\n"
    "positions and spacings have a double's.\n"
    "The files appear together when the run has succeeded, never half-written. If the\n"
    "directory exists, only the files named above are replaced; other files stay.\n"
    "\n"
    "The default estimator is the exact OpenCL kernel (Lambert's contour integral over the\n"
    "visible part of each source). --reference uses an independent check instead: about\n"
    "n*n sample points on each source face (a Fibonacci lattice) with exact ray-solid tests\n"
    "on the host, in double precision; its error falls about as 1/n^2, its time grows as n^2;\n"
    "it computes the direct light only.\n"
    "\n"
    "Photometric luminaires (scene key luminaires:, model: area | point): the area model,\n"
    "the default where the file gives a flat luminous opening, integrates the opening's\n"
    "fitted luminance exactly over the part each point sees (penumbrae); the point model\n"
    "puts the distribution at the photometric centre (hard shadows). Both run on the\n"
    "device and with --reference; summary.json lists each luminaire's model and fit.\n"
    "\n"
    "Interreflection: every face of a solid with a material reflects diffusely (its\n"
    "reflectance); faces without a material are black, and a warning names their solids.\n"
    "Sources emit and neither reflect nor block reflected light; openings let it out. The\n"
    "faces are cut into elements of at most --element-size m (default 0.5), finer where the\n"
    "direct light is uneven; the transfer between elements and the final gather at each\n"
    "point are the same exact contour integral as the direct light (docs/method.md).\n"
    "\n"
    "Examples:\n"
    "  penumbra grid data/office.yaml -o out/office\n"
    "  penumbra grid data/office.yaml -o out/desk --grid desk-1-top --reference\n"
    "  penumbra grid data/office.yaml -o out/narrow --set window_width_m=1.2\n"
    "  penumbra grid data/office.yaml -o out/office --plot --range 0:1500\n"
    "\n"
    "Exit status: 0 done; 1 error (device, output directory, options); 2 invalid scene, reported\n"
    "as file:line: key: message. Nothing is written unless the run succeeds.";

inline constexpr const char* kSweep =
    "Run a parameter study: every case (one set of values of the base scene's parameters) is "
    "computed like `penumbra grid` on one device with one compiled program, into its own folder, "
    "and all of them are compared in one table.";

inline constexpr const char* kSweepFooter =
    "The study file (docs/sweeps.md) names a base scene whose numeric fields use its parameters\n"
    "(\"${3.0 - window_width_m/2}\"), the values each parameter takes (values, range, linspace)\n"
    "and how they combine (grid: every combination; zip: the i-th values together).\n"
    "\n"
    "Outputs (in the folder given with -o):\n"
    "  results.csv          one row per case: case_id, every parameter, Eavg_lx, Emin_lx,\n"
    "                       Emax_lx, U0 = Emin/Eavg, Ud = Emin/Emax (\"Eavg_lx@<grid>\" when the\n"
    "                       study has several grids); with a sky DFavg_pct, DFmin_pct,\n"
    "                       DFmedian_pct and EN17037_level (0 none, 1 minimum, 2 medium,\n"
    "                       3 high); paths of the case's images\n"
    "  design-explorer.csv  the same as in:/out:/img: columns (Design Explorer)\n"
    "  charts/              each metric against each varied parameter (PNG, rendered through\n"
    "                       X: where there is no display, run under xvfb-run -a)\n"
    "  cases/<case-id>/     what `penumbra grid` writes (<grid>.csv, <grid>.res, summary.json),\n"
    "                       its plots (plots: true; <grid>.png, surfaces.png, through X) and\n"
    "                       case.json (values, metrics, fingerprint, images)\n"
    "  study.json           the cases and their fingerprints, for --resume and merge\n"
    "\n"
    "The metrics are of the total illuminance (direct + interreflected), as in `penumbra grid`;\n"
    "--direct-only computes the direct light alone, --element-size sets the interreflection's\n"
    "elements (m).\n"
    "\n"
    "Nothing is lost: a case folder appears only when complete. Running the same command again\n"
    "skips the finished cases (recomputing those whose scene, values, grids or estimator changed)\n"
    "and rebuilds the tables; after a kill or Ctrl-C, rerun it (or add --resume).\n"
    "With --shard I/N a run computes every N-th case; run the N shards anywhere (GNU parallel,\n"
    "any scheduler: docs/cluster.md) and join their folders with `penumbra merge`.\n"
    "With --slurm --shards N nothing is computed here: OUT/slurm/sweep.sbatch (a job array, one\n"
    "task per shard) and OUT/slurm/merge.sbatch (after every shard succeeded) are submitted with\n"
    "sbatch, and OUT/results.csv appears when the merge job is done. --slurm-opt passes options\n"
    "to sbatch, --dry-run only writes the scripts, --resume resubmits the unfinished shards.\n"
    "\n"
    "Examples:\n"
    "  penumbra sweep studies/window-width.yaml -o out/window-width\n"
    "  penumbra sweep studies/panel-spacing-flux.yaml -o out/shard-1 --shard 1/2\n"
    "  penumbra sweep studies/panel-spacing-flux.yaml -o /shared/out/panels --slurm --shards 4 \\\n"
    "      --slurm-opt \"--partition=compute --time=00:30:00\"\n"
    "\n"
    "Exit status: 0 done (or submitted); 1 error (device, output folder, options, sbatch);\n"
    "2 invalid study, or a case whose scene is invalid (named with its values), as\n"
    "file:line: key: message. A study with an invalid case computes (and submits) nothing.";

inline constexpr const char* kMerge =
    "Join the output folders of the shards of one sweep (penumbra sweep --shard I/N) into one: "
    "the case folders, results.csv, design-explorer.csv and the charts, as one unsharded run "
    "would have written them.";

inline constexpr const char* kMergeFooter =
    "Every folder must hold the same study (same cases, values, scenes and estimator). Cases\n"
    "missing from every folder are reported and left out of the table.\n"
    "\n"
    "Example:\n"
    "  penumbra merge out/shard-1 out/shard-2 -o out/panels";

inline constexpr const char* kDevices =
    "List the OpenCL devices: index (what --device takes), type, name, platform, compute units.";

inline constexpr const char* kGlare =
    "Rate discomfort glare: the Unified Glare Rating (UGR, CIE 117-1995) of every observer of the "
    "scene ('observers:') along each of its lines of sight, from the exact solid angle of the "
    "part of each luminous area the eye sees and the interreflected light at the eye.";

inline constexpr const char* kGlareFooter =
    "UGR = 8 log10(0.25/L_b * sum L^2 omega / p^2) (docs/glare.md), per glare source:\n"
    "  L      its luminance towards the eye (cd/m²): a source's own; a luminaire's intensity\n"
    "         towards the eye over its luminous area projected across that direction\n"
    "  omega  the solid angle of the part of its luminous area the eye sees past the solids\n"
    "         (sr), exact (not the far-field A_p/d²)\n"
    "  p      the Guth position index; a source below the line of sight, behind the eye or\n"
    "         beyond H/R = 1.9 or T/R = 3 is left out, and counted\n"
    "  L_b    the background luminance E_ind/pi (cd/m²): the interreflected illuminance at the\n"
    "         eye on the plane facing the line of sight. With --direct-only, or in a black\n"
    "         room, L_b = 0 and UGR is undefined (reported as such, never as infinity).\n"
    "Each observer is rated along its 'look', or along +x, +y, -x, -y when it gives none.\n"
    "\n"
    "Outputs (in the directory given with -o):\n"
    "  <entry>.csv          one row per eye and line of sight: eye (m), look, UGR, the\n"
    "                       strictest EN 12464-1 limit it meets (16, 19, 22, 25, 28), why it\n"
    "                       is undefined, L_b (cd/m²), E_ind (lx), the sum, the sources rated\n"
    "                       and left out, the strongest source and its share (%)\n"
    "  <entry>-sources.csv  one row per source of each rating: L (cd/m²), omega and the\n"
    "                       far-field A_p/d² (sr), p, L²omega/p² and its share (%)\n"
    "  summary.json         the method, every rating with its sources, UGR_max\n"
    "A table is printed at the end. The files appear together when the run has succeeded.\n"
    "\n"
    "Examples:\n"
    "  penumbra glare data/office-glare.yaml -o out/glare\n"
    "  penumbra glare data/office-glare.yaml -o out/glare --element-size 0.25\n"
    "\n"
    "Exit status: 0 done; 1 an error (device, output); 2 an invalid scene, reported as\n"
    "file:line: key: message.";

inline constexpr const char* kLuminaire =
    "Show what a photometric file (IES LM-63 .ies or EULUMDAT .ldt) holds, as penumbra reads it: "
    "format, photometric type, symmetry, lamps, light output ratio, luminous opening, peak "
    "intensity, and the flux of its table against the flux the file states.";

inline constexpr const char* kLuminaireFooter =
    "What the lines mean (docs/photometry.md):\n"
    "  photometric type  C: planes C about the vertical axis, gamma from the nadir (0) to the\n"
    "                    zenith (180); B and A: floodlight and automotive systems (H, V)\n"
    "  symmetry          which planes the file stores; the rest of the sphere is mirrored\n"
    "  lamps             lamp flux (lm) the relative table is scaled to; EULUMDAT tables are\n"
    "                    in cd/klm and are converted to cd with it\n"
    "  LOR               light output ratio: luminaire flux / lamp flux (EULUMDAT LORL; IES\n"
    "                    files state it with the keyword [_LOR], in %)\n"
    "  opening           the luminous area in metres (IES feet converted), along C0-C180\n"
    "                    (length), C90-C270 (width) and the vertical (height)\n"
    "  peak intensity    the largest value of the table (cd) and its angles\n"
    "  flux of the table the luminous flux (lm) of the table by the zonal method; it should\n"
    "                    equal lamp lumens x LOR within 0.1 %: more means a coarse or\n"
    "                    inconsistent table\n"
    "\n"
    "--ugr-table (docs/glare.md): the UGR table by the CIE 190:2010 tabular method, rooms X x Y\n"
    "from 2H x 2H to 12H x 8H (H = 2 m from the eye, 1.2 m, to the luminaires), the five\n"
    "reflectance sets ceiling/walls/floor, viewed crosswise and endwise, at spacing S = 0.25H\n"
    "(the layout DIALux shows) and S = 1.0H (CIE 190's standard condition); with -o DIR also\n"
    "DIR/<stem>-ugr-table.csv. The table holds for the file's flux Phi0; for Phi add\n"
    "8 log10(Phi/Phi0).\n"
    "\n"
    "Examples:\n"
    "  penumbra luminaire data/luminaires/narrow-downlight.ies\n"
    "  penumbra luminaire data/luminaires/batwing.ldt\n"
    "  penumbra luminaire data/luminaires/lambertian-panel.ldt --ugr-table -o out/ugr\n"
    "\n"
    "Exit status: 0 read; 1 the file cannot be read or has an unknown extension; 2 malformed,\n"
    "reported as file:line: field: message.";

inline constexpr const char* kRender =
    "Render the scene's views: luminance images (cd/m²) with exact direct illuminance at every "
    "visible point, soft shadows included, and the light the room's surfaces reflect (unless "
    "--direct-only), plus illuminance and face-id images.";

inline constexpr const char* kRenderFooter =
    "Outputs (in the directory given with -o), per view:\n"
    "  <view>.exr         luminance L = reflectance * E / pi per RGB channel, E the total\n"
    "                     (direct + interreflected) or with --direct-only the direct, cd/m², "
    "32-bit\n"
    "                     float linear RGB; a visible source shows its own luminance\n"
    "  <view>.hdr         the same as Radiance RGBE radiance, W/(sr m²) = cd/m² / 179, with\n"
    "                     the camera as VIEW= (pvalue, falsecolor, evalglare; about 1 %)\n"
    "  <view>.E.exr       illuminance E (lx) at the surface each pixel's centre sees; 0 on\n"
    "                     sources and where the view leaves the scene\n"
    "  <view>.faceid.exr  which face each pixel shows (0: none; solids' faces first, then the\n"
    "                     sources'), for the tone map and for picking\n"
    "  <view>.png         the display image: the HDR luminance tone-mapped by --display\n"
    "                     (Fang's constraint hierarchy by default; see `penumbra tonemap`)\n"
    "  <view>.tonemap.json  the tone map's statistics (variables, rows, iterations, seconds)\n"
    "  render.json        scene, parameters, device, options, and per view its camera, the\n"
    "                     share of samples computed exactly, and the time of each stage (s)\n"
    "Each image's header records the view, the scene, its parameters, the units, the light\n"
    "(penumbra:light: total (direct + interreflected) or direct only) and the luminaires'\n"
    "maintenance factors.\n"
    "\n"
    "Views are declared in the scene (docs/scene-format.md, \"Views\"):\n"
    "  views: [{name: from-door, eye: [0.6, 3.6, 1.6], target: [3, 0, 1.2], fov: 75,\n"
    "           size: [1280, 720]}]\n"
    "eye and target in m; up defaults to [0, 0, 1]; fov is the horizontal angle in degrees.\n"
    "\n"
    "Speed: --interval k computes E exactly every k pixels along each row and interpolates\n"
    "between, except across a change of face or of any source's shadow class (lit, penumbra,\n"
    "umbra), where every pixel is exact. k = 1 (the default) is exact everywhere; 4 to 8 is\n"
    "usually indistinguishable (render.json reports the share computed exactly). The\n"
    "interreflected light is gathered exactly every 8 pixels, at every pixel next to a face\n"
    "edge and wherever it bends, and interpolated within a face between (docs/render.md).\n"
    "--spp 4 (9, 16) averages 2 x 2 (3 x 3, 4 x 4) samples per pixel for smooth edges.\n"
    "\n"
    "Examples:\n"
    "  penumbra render data/office.yaml -o out/office\n"
    "  penumbra render data/office.yaml --view from-door -o out/ --interval 4 --spp 4\n"
    "  penumbra render data/office.yaml -o out/narrow --set window_width_m=1.2\n"
    "  penumbra render data/office.yaml -o out/ --display linear --black 0.05\n"
    "\n"
    "Exit status: 0 done; 1 error (device, output directory, options, unknown view); 2 invalid\n"
    "scene. Nothing is written unless every view rendered.";

inline constexpr const char* kToneMap =
    "Map an HDR render to display values (PNG) with Fang's constraint hierarchy: the contrast "
    "across every visible edge is kept, large areas drift slowly, the display's black and white "
    "are hard limits.";

inline constexpr const char* kToneMapFooter =
    "Reads <view>.exr (linear RGB, cd/m2) and <view>.faceid.exr (which face each pixel shows)\n"
    "as `penumbra render` writes them. Writes the PNG (8-bit drive values, tagged sRGB) and,\n"
    "beside it, <view>.tonemap.json: variables, rows per level, outer iterations, residual per\n"
    "level, seconds. Method and defaults: docs/tonemap.md.\n"
    "\n"
    "Examples:\n"
    "  penumbra tonemap out/from-door.exr -o out/from-door.png\n"
    "  penumbra tonemap out/from-door.exr --faces out/from-door.faceid.exr -o out/linear.png \\\n"
    "      --display linear --black 0.05 -v";

}  // namespace penumbra::help
