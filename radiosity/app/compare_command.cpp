// `radiosity compare SCENE.obj --out DIR`: every render method of render_methods.h from the same
// camera, scene and BVH, each written as <method>.exr, and a labelled contact sheet compare.png
// (method, the Heckbert paths it captures, samples, time) with compare.json.
#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "radiosity/app/commands.h"
#include "radiosity/app/options/camera_options.h"
#include "radiosity/app/options/exposure_option.h"
#include "radiosity/app/options/gather_options.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/options/solve_option_group.h"
#include "radiosity/app/render_world.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/output/contact_sheet.h"
#include "radiosity/output/image_io.h"
#include "radiosity/pipeline/thread_limit.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/exposure_weights.h"
#include "radiosity/render/image_renderer.h"
#include "radiosity/render/render_methods.h"

namespace rad {
namespace {

struct CompareOptions {
  SolveOptions solve;
  std::vector<std::string> methods;                // empty: every method
  int spp = 0;                                     // 0: each method's default
  FinalGatherOptions gather = {kRenderGather, 0};  // radiosity's --gather (as many shadow rays)
  int columns = 3;
  CameraOptions camera;  // --camera, --width, --height
  ExposureOption exposure;
};

struct MethodResult {
  const RenderMethod* method = nullptr;
  RenderOutput render;
  int spp = 0;
  double seconds = 0;  // the solve (if any) plus the render
};

std::string formatSeconds(double s) {
  std::ostringstream out;
  out.precision(s < 10 ? 2 : 3);
  out << s << " s";
  return out.str();
}

void runCompare(const CLI::App& command, CompareOptions& o) {
  // Check everything that can be wrong before any long work.
  checkGatherOptions(o.gather);
  if (o.columns < 1) throw InputError("--columns must be >= 1");
  o.exposure.check();
  std::vector<const RenderMethod*> methods;
  if (o.methods.empty()) {
    for (const RenderMethod& m : renderMethods()) methods.push_back(&m);
  } else {
    for (const std::string& name : o.methods) {
      const RenderMethod& m = findRenderMethod(name);
      for (const RenderMethod* seen : methods)
        if (seen == &m) throw InputError("--methods names '" + name + "' twice");
      methods.push_back(&m);
    }
  }
  bool solves = false;
  for (const RenderMethod* m : methods) solves = solves || m->needsSolve;
  if (solves) {
    finishSolveOptions(command, o.solve);
  } else {
    const std::string why = "none of the --methods solves radiosity";
    refuseGatherOptions(command, why + ": there is no solution to gather from");
    finishWithoutSolve(command, o.solve, why);
  }
  const ResolvedCamera resolved = resolveCamera(o.camera, o.solve.scenePath);
  const Camera& camera = resolved.camera;
  const std::string& source = resolved.file;
  RenderWorld world(o.solve, source);

  const ThreadLimit threadLimit(o.solve.threads);
  const int threads = threadLimit.threads();

  // The motion description is checked against the scene before the first render.
  for (const RenderMethod* method : methods)
    if (method->usesMotion && !world.motionSpec().empty()) world.viewFor(*method);

  std::vector<MethodResult> results;
  for (const RenderMethod* method : methods) {
    throwIfInterrupted();
    const double solveBefore = world.solveSeconds();
    const RenderWorld::View view = world.viewFor(*method);
    const auto integrator = method->makeIntegrator(
        MethodInputs{*view.scene, view.radiosity, view.directIrradiance, o.gather, &camera});
    MethodResult r;
    r.method = method;
    r.spp = o.spp > 0 ? o.spp : method->defaultSpp;
    RenderSettings settings;
    settings.samplesPerPixel = r.spp;
    settings.seed = o.solve.seed;
    r.render = renderMethodImage(camera, *integrator, settings);
    r.seconds = world.solveSeconds() - solveBefore + r.render.seconds;
    logInfo("compare: " + method->name + " (" + method->paths + "), " + std::to_string(r.spp) +
            " spp, " + formatSeconds(r.seconds));
    results.push_back(std::move(r));
  }

  // One exposure for every tile, so that brightness compares: the path tracer's (the unbiased
  // reference) unless --exposure is given, else the first method's.
  const MethodResult* reference = &results.front();
  for (const MethodResult& r : results)
    if (r.method->name == "path") reference = &r;
  // Auto exposure from the lit surfaces in view: emitter and sky pixels do not set it.
  const ToneMap toneMap = o.exposure.toneMap([&] {
    return ToneMap::autoExposure(reference->render.image.pixels,
                                 exposureWeights(camera, *world.viewFor(*reference->method).scene));
  });
  std::vector<SheetTile> tiles;
  for (const MethodResult& r : results) {
    // Short lines, so that the font can be doubled on modest tiles; a method's time includes
    // its solve (compare.json has both).
    tiles.push_back({r.render.image,
                     {r.method->name, r.method->paths,
                      std::to_string(r.spp) + " spp, " + formatSeconds(r.seconds)}});
  }
  const ImageRgb sheet = composeContactSheet(tiles, toneMap, o.columns);

  throwIfInterrupted();
  OutputSection writing;  // Ctrl-C now waits until every file has its final name (or none has)
  ensureDirectory(o.solve.outputDir);
  const std::filesystem::path dir(o.solve.outputDir);
  std::vector<std::unique_ptr<AtomicPath>> files;
  nlohmann::json list = nlohmann::json::array();
  for (const MethodResult& r : results) {
    files.push_back(std::make_unique<AtomicPath>((dir / (r.method->name + ".exr")).string()));
    writeExr(files.back()->tempPath(), r.render.image);
    list.push_back({{"method", r.method->name},
                    {"paths", r.method->paths},
                    {"integrator", r.method->summary},
                    {"samples_per_pixel", r.spp},
                    {"seconds", r.seconds},  // solve (if any) + render
                    {"render_seconds", r.render.seconds},
                    {"rays", r.render.rays.total()},
                    {"exr", r.method->name + ".exr"}});
  }
  files.push_back(std::make_unique<AtomicPath>((dir / "compare.png").string()));
  writePng(files.back()->tempPath(), sheet, ToneMap{1.0});
  nlohmann::json skipped = nlohmann::json::array();
  for (const SkipNote& s : world.skipped()) skipped.push_back({{"what", s.what}, {"why", s.why}});
  const nlohmann::json report = {
      {"scene", o.solve.scenePath},
      {"camera", source.empty() ? o.solve.scenePath : source},
      {"width", camera.width},
      {"height", camera.height},
      {"seed", o.solve.seed},
      {"threads", threads},
      {"methods", list},
      {"contact_sheet", "compare.png"},
      {"tone_map",
       {{"exposure", toneMap.exposure},
        {"operator",
         "every tile: sRGB OETF(clamp(exposure * L, 0, 1)), one exposure for all: "
         "the path tracer's 99th percentile of luminance unless --exposure"}}},
      {"units", "<method>.exr hold linear radiance, W/(m^2 sr), for scenes in metres"},
      {"skipped", skipped},
  };
  AtomicFile json((dir / "compare.json").string());
  json.stream() << report.dump(2) << "\n";
  for (auto& f : files) f->commit();
  json.commit();
  logInfo("wrote compare.png, compare.json and " + std::to_string(results.size()) +
          " EXR images to " + o.solve.outputDir);
}

}  // namespace

void registerCompareCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Render the scene with every method and write a labelled contact sheet");
  cmd->add_option("scene", o->solve.scenePath,
                  std::string(kSceneFileHelp) + "; camera from <scene>.camera.json")
      ->required();
  cmd->add_option("--out", o->solve.outputDir,
                  "Output directory for compare.png, compare.json and <method>.exr")
      ->required();
  cmd->add_option("--methods", o->methods,
                  "Methods to compare, in this order (default: all: " + renderMethodNames() + ")")
      ->delimiter(',');
  cmd->add_option("--spp", o->spp, "Samples per pixel for every method (default: each method's)")
      ->check(positiveNumber());
  addGatherRaysOption(*cmd, o->gather, "diffuse eye hit (radiosity)");
  cmd->add_option("--columns", o->columns, "Tiles per row of the contact sheet")
      ->default_val(o->columns);
  addCameraOptions(*cmd, o->camera, CameraOverrides::SizeOnly);
  o->exposure.add(*cmd,
                  "Exposure of every tile (default: the path tracer's 99th percentile maps to 1)");
  addSolveOptions(*cmd, o->solve);
  addCommonFlags(*cmd);
  cmd->callback([&run, cmd, o] { run = [cmd, o] { runCompare(*cmd, *o); }; });
}

}  // namespace rad
