// The commands of `glint`, each a subcommand of the one command line (cli/command_line.h): each
// add…Command adds its command, options bound to its own settings, to `glint`.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// `glint bench [--frames N] [--quick] [--json FILE]`: times the standard scenes (bench_scenes.h)
// at 1280×720, each against the bare shading pass of the same material and lights measured in
// the same run (a ratio), then the headless cold start, thumbnails per second and peak memory.
// Prints an aligned table; --json writes the same figures for comparison over time.
// Exit code: 0 measured, 1 a scene or child process failed, 2 bad arguments or no context.
void addBenchCommand(CLI::App& glint);

// `glint cmf -o OUT.png [--size WxH]`: the plot of the CIE 1931 colour matching functions
// (app/classroom/cmf_plot.h), drawn headless through the overlay canvas, as the editor's
// View ▸ Colour matching functions window shows it.
// Exit code: 0 written, 2 bad arguments, no GL context or failure to write.
void addCmfCommand(CLI::App& glint);

// `glint export IN -o OUT.mtl|OUT.gltf`: writes Glint materials (from a material file, a scene,
// or another interchange file) as a Wavefront .mtl library or a self-contained glTF 2.0 file.
// Conversion only; nothing is rendered.
// Exit code: 0 written, 2 bad arguments or input, or failure to write.
void addExportCommand(CLI::App& glint);

// `glint info FILE`: what a file holds, for every format Glint reads (interchange files'
// materials, lights and meshes with their names; a mesh's counts; a .brdf's or .bparam's
// parameters; a scene's materials, objects and lights), and the warnings opening it gives.
// Reading only; nothing is rendered.
// Exit code: 0 listed, 2 bad arguments or a file that does not load.
void addInfoCommand(CLI::App& glint);

// `glint lessons [LIST.json] [--check] [--render DIR] [--width N]`: lists the classroom lessons
// (core/classroom/lessons.h), checks that every lesson's scene loads, or renders one PNG per lesson.
// Stepping through lessons in the editor lives in app/classroom/lessons_view.cpp.
// Exit code: 0 listed / all loaded / all rendered, 1 some lesson failed to load or render, 2 bad
// arguments or an unreadable lesson list.
void addLessonsCommand(CLI::App& glint);

// `glint models [--markdown]`: lists the BRDF models (id, label), or writes the
// models-and-parameters reference (docs/models.md) as Markdown. Exit code: 0.
void addModelsCommand(CLI::App& glint);

// `glint presets [NAME -o FILE.json]`: lists the material presets (name, category, model,
// source), or writes one as a material file. The table itself lives in core/brdf/presets.h.
// Exit code: 0 listed or written, 2 unknown preset, bad arguments or write failure.
void addPresetsCommand(CLI::App& glint);

// `glint render SCENE -o OUT.png|OUT.exr [--size WxH] [--msaa N] [--reference [--samples N]]`:
// renders a scene file (or a material file, on the preview stage) headless (OSMesa, or the CPU
// reference, whose environment light --samples integrates by Monte-Carlo) and writes the image;
// `--probe X,Y` prints the surface probe there, `--overlay NAME` draws a classroom overlay
// (cli/render_overlays.h) over the PNG.
// Exit code: 0 written, 2 bad arguments or input, or failure to render.
void addRenderCommand(CLI::App& glint);

// `glint snapshot SUITE [--out DIR] [--update] [--update-case NAME]... [--jobs N] [--shard I/N]`:
// renders every case of a snapshot suite headless in one process and compares it with its
// golden; writes failing images, an HTML report and JUnit XML. Suite format: docs/snapshot-testing.md.
// Exit code: 0 all passed, 1 some case failed or errored, 2 the run could not happen (bad
// arguments, bad suite or manifest, no OpenGL context, output not writable).
void addSnapshotCommand(CLI::App& glint);

// `glint spectral SCENE.json -o OUT.png|OUT.exr [--size WxH] [--band NM,FWHM] [--cauchy-b B]
// [--wavelengths N]`: the scene rendered per wavelength on the CPU and converted to RGB through
// the CIE 1931 matching functions (core/colour/spectral_render.h).
// Exit code: 0 written, 2 bad arguments, bad input or failure to write.
void addSpectralCommand(CLI::App& glint);

// `glint thumbnails DIR -o OUTDIR [--size N] [--jobs N] [--columns N]`: renders every material
// (and scene) file in DIR headless, one PNG each (materials on the preview stage), and a
// labelled contact sheet, all in one process.
// Exit code: 0 all written, 1 some files could not be rendered (the rest were), 2 nothing could
// be done (bad arguments, unreadable directory, no context, no font).
void addThumbnailsCommand(CLI::App& glint);

}  // namespace glint
