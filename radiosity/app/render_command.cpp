// `radiosity render SCENE.obj --out DIR`: images from the scene's camera by one of the methods of
// render_methods.h (final gather over the radiosity solution, path tracing, the classic ones).
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "radiosity/app/commands.h"
#include "radiosity/app/render_world.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/image_io.h"
#include "radiosity/pipeline/saved_solution.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/exposure_weights.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/image_renderer.h"
#include "radiosity/render/path_expression.h"
#include "radiosity/render/path_renderer.h"
#include "radiosity/render/render_methods.h"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;

struct RenderCommandOptions {
  SolveOptions solve;
  std::string solverName = "progressive";
  std::string method = "radiosity";
  int gather = kRenderGather;
  int lightRays = 0;      // 0: as many as gather
  int spp = 0;            // 0: the method's default
  bool adaptive = false;  // --adaptive: spp is the mean, shared out by the pixels' spread
  std::string cameraFile;
  std::vector<double> position, lookAt, up;
  std::optional<double> vfov, lensRadius, focusDistance, exposure;
  std::optional<int> width, height;
  bool freshSolve = false;             // solve even when --out holds a reusable solution
  std::string solutionDir;             // --solution: reuse the solution `solve` saved there
  std::string paths;                   // --paths: Heckbert expression (path, bdpt)
  std::optional<int> bouncesSeparate;  // --bounces-separate K
  std::string mis = "power";           // --mis (bdpt)
};

Eigen::Vector3d toVector(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// render.json's `adaptive`: null for a uniform render; else the samples taken per pixel.
nlohmann::json adaptiveReport(const RenderOutput& render, int spp, bool asked) {
  if (!asked) return nullptr;
  if (render.samples.empty())
    return {{"applied", false}, {"why", "--spp below " + std::to_string(kMinAdaptiveSpp)}};
  int64_t total = 0;
  for (int n : render.samples) total += n;
  return {{"applied", true},
          {"first_pass_spp", spp / 4},
          {"mean_spp", double(total) / render.samples.size()},
          {"max_spp", *std::max_element(render.samples.begin(), render.samples.end())},
          {"min_spp", *std::min_element(render.samples.begin(), render.samples.end())}};
}

// The camera from --camera, the scene's sidecar, the scene's own (glTF) or the command line;
// `source` gets the file it came from ("" for none), which also holds the motion-blur fields.
Camera resolveCamera(const RenderCommandOptions& o, std::string& source) {
  Camera camera;
  source = o.cameraFile;
  if (source.empty()) {
    const std::string sidecar = cameraSidecarPath(o.solve.scenePath);
    if (std::filesystem::exists(sidecar)) source = sidecar;
  }
  std::optional<Camera> sceneCamera;  // a glTF scene's own camera, when there is no sidecar
  if (source.empty()) sceneCamera = findSceneCamera(o.solve.scenePath);
  if (!source.empty()) {
    camera = loadCamera(source);
  } else if (sceneCamera) {
    camera = *sceneCamera;
  } else if (o.position.empty() || o.lookAt.empty()) {
    throw InputError(o.solve.scenePath, 0,
                     "no camera: write " + cameraSidecarPath(o.solve.scenePath) +
                         " or pass --camera FILE, or --position and --look-at");
  }
  if (!o.position.empty()) camera.position = toVector(o.position);
  if (!o.lookAt.empty()) camera.lookAt = toVector(o.lookAt);
  if (!o.up.empty()) camera.up = toVector(o.up);
  if (o.vfov) camera.vfovDegrees = *o.vfov;
  if (o.width) camera.width = *o.width;
  if (o.height) camera.height = *o.height;
  if (o.lensRadius) camera.lensRadius = *o.lensRadius;
  if (o.focusDistance) camera.focusDistance = *o.focusDistance;
  validateCamera(
      camera, source.empty() ? "command line camera" : source + " (with command-line overrides)");
  return camera;
}

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// Options of the path-type and Neumann-term images that cannot work together.
void checkPathOptions(const RenderCommandOptions& o) {
  const bool pathMethod = o.method == "path" || o.method == "bdpt";
  if (!o.paths.empty() && !pathMethod)
    throw InputError("--paths needs --method path or bdpt (--method " + o.method +
                     " does not follow light paths one by one)");
  if (o.bouncesSeparate && !pathMethod && o.method != "radiosity")
    throw InputError("--bounces-separate needs --method path, bdpt or radiosity (--method " +
                     o.method + " does not sum a Neumann series)");
  if (o.bouncesSeparate && *o.bouncesSeparate < 0)
    throw InputError("--bounces-separate must be >= 0 (the highest Neumann term to write)");
  if (!o.paths.empty() && o.bouncesSeparate)
    throw InputError("--paths and --bounces-separate cannot be combined: give one of them");
  if (o.mis != "power" && o.mis != "balance")
    throw InputError("unknown --mis '" + o.mis + "' (expected power or balance)");
  if (o.mis != "power" && o.method != "bdpt")
    throw InputError("--mis applies to --method bdpt only");
  if (o.bouncesSeparate && o.method == "radiosity" && o.solverName != "progressive" &&
      o.solverName != "jacobi")
    throw InputError(
        "--bounces-separate with --method radiosity runs --solver jacobi (its iterates "
        "are the Neumann terms); --solver " +
        o.solverName + " cannot give them");
  if (o.bouncesSeparate && o.solve.bounces >= 0)
    throw InputError("--bounces-separate K sets the Jacobi bounces itself: leave out --bounces");
}

void runRender(const CLI::App& command, RenderCommandOptions& o) {
  const auto start = Clock::now();
  const RenderMethod& method = findRenderMethod(o.method);
  checkPathOptions(o);
  // The path expression is parsed before any long work: a malformed one fails at once.
  std::optional<ExpressionBinning> pathFilter;
  if (!o.paths.empty()) pathFilter.emplace(PathExpression::parse(o.paths));
  if (o.gather < 0) throw InputError("--gather must be >= 0");
  if (o.lightRays < 0) throw InputError("--light-rays must be >= 0");
  if (o.spp < 0) throw InputError("--spp must be >= 1");
  if (o.exposure && !(*o.exposure > 0)) throw InputError("--exposure must be > 0");
  const bool radiosity = method.needsSolve;
  const bool separateBounces = o.bouncesSeparate.has_value();
  if (radiosity && separateBounces) {
    // The Neumann terms are the Jacobi iterates: B_k − B_{k−1} = (ρF)^k E.
    o.solverName = "jacobi";
    o.solve.bounces = *o.bouncesSeparate;
    o.solve.keepBounceTerms = true;
  }
  const int spp = o.spp > 0 ? o.spp : method.defaultSpp;
  finishSolveOptions(command, o.solve, o.solverName,
                     radiosity ? "" : "--method " + method.name + " does not solve radiosity");
  std::string cameraSource;
  // Before any long work: a bad camera or motion description fails at once.
  const Camera camera = resolveCamera(o, cameraSource);
  RenderWorld world(o.solve, cameraSource,
                    {o.solutionDir, o.freshSolve ? std::string() : o.solve.outputDir});

  const int threads = o.solve.threads > 0 ? o.solve.threads : tbb::info::default_concurrency();
  tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(threads));
  nlohmann::json skipped = nlohmann::json::array();
  auto skip = [&](const std::string& what, const std::string& why) {
    logInfo("skipped: " + what + " (" + why + ")");
    skipped.push_back({{"what", what}, {"why", why}});
  };

  // The scene, its mesh and BVH, and (for methods that need it) the radiosity solution.
  const RenderWorld::View view = world.viewFor(method);
  const RenderScene& renderScene = *view.scene;
  const PatchMesh& mesh = renderScene.mesh();
  for (const SkipNote& s : world.skipped()) skipped.push_back({{"what", s.what}, {"why", s.why}});
  if (!renderScene.hasSpecular())
    skip("specular branch", "the scene has no mirror or glass material");

  std::unique_ptr<Integrator> integrator = method.makeIntegrator(
      MethodInputs{renderScene, view.radiosity, o.gather, &camera,
                   o.mis == "balance" ? MisHeuristic::Balance : MisHeuristic::Power, o.lightRays});
  if (radiosity && o.gather == 0)
    skip("final gather", o.lightRays > 0
                             ? "--gather 0 --light-rays N: the indirect light is the solution's"
                             : "--gather 0: interpolated radiosity preview");
  if (o.method == "bdpt" && camera.lensRadius > 0)
    skip("light tracing (t = 1)", "it needs a pinhole camera (lens radius 0)");
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.adaptive = o.adaptive;
  settings.seed = o.solve.seed;
  // Path types and Neumann terms: images beside the main one (written as bounce_*.exr).
  std::vector<ImageRgb> bounceImages;
  RenderOutput render;
  const auto* pathIntegrator = dynamic_cast<const PathIntegrator*>(integrator.get());
  // The path renderer sums whole light paths per pixel (and bdpt's light tracing into others):
  // it has no per-pixel second pass.
  if (o.adaptive && pathIntegrator)
    throw InputError("--adaptive: --method " + method.name +
                     " is not sampled adaptively; use it with radiosity, direct, whitted or "
                     "distribution");
  if (pathIntegrator && (pathFilter || separateBounces)) {
    std::optional<BounceBinning> bounceBins;
    if (separateBounces) bounceBins.emplace(*o.bouncesSeparate);
    const PathBinning* binning = pathFilter   ? static_cast<const PathBinning*>(&*pathFilter)
                                 : bounceBins ? static_cast<const PathBinning*>(&*bounceBins)
                                              : nullptr;
    PathRenderOutput out = renderPathImage(camera, *pathIntegrator, settings, binning);
    render = std::move(out.full);
    if (pathFilter) {  // the main image holds the matching paths only
      render.image = std::move(out.bins[0].image);
      render.variance = std::move(out.bins[0].variance);
    }
    if (bounceBins)
      for (RenderOutput& b : out.bins) bounceImages.push_back(std::move(b.image));
  } else {
    render = renderMethodImage(camera, *integrator, settings);
    if (separateBounces && radiosity) {
      // The eye pass of each term: its interpolated B_k/π at the first diffuse hit (gather 0),
      // seen through mirrors and glass; linear in B, so the terms sum to the --gather 0 image.
      RenderSettings quiet = settings;
      quiet.showProgress = false;
      for (const std::vector<Rgb>& term : world.solved()->solution.bounceTerms) {
        const FinalGather eyePass(renderScene, term, FinalGatherOptions{0});
        bounceImages.push_back(renderImage(camera, eyePass, quiet).image);
      }
      if (o.gather > 0)
        skip("final gather in the bounce_* images",
             "each Neumann term is shown by the interpolated preview (--gather 0), which they sum "
             "to");
    }
  }
  if (render.rays.gathersSkipped > 0)
    skip("gathers at " + std::to_string(render.rays.gathersSkipped) + " eye-ray hits",
         "the surface hit reflects nothing (ρ = 0): its radiance is its Ke");
  const double solveSeconds = world.solveSeconds(), bvhSeconds = world.bvhSeconds();

  // Outputs: EXR (linear radiance), PNG (tone-mapped), JSON (report); renamed together at the end.
  auto t = Clock::now();
  throwIfInterrupted();
  OutputSection writing;  // Ctrl-C now waits until every file has its final name (or none has)
  ensureDirectory(o.solve.outputDir);
  const std::filesystem::path dir(o.solve.outputDir);
  // Auto exposure from the lit surfaces in view: emitter and sky pixels do not set it.
  const ToneMap toneMap =
      o.exposure ? ToneMap{*o.exposure}
                 : ToneMap::autoExposure(render.image.pixels, exposureWeights(camera, renderScene));
  AtomicPath exr((dir / "render.exr").string());
  writeExr(exr.tempPath(), render.image);
  AtomicPath png((dir / "render.png").string());
  writePng(png.tempPath(), render.image, toneMap);
  // bounce_k: the term T^k L_e; bounce_sum_k: the terms 0..k. PNGs share the main exposure.
  std::vector<std::unique_ptr<AtomicPath>> bounceFiles;
  nlohmann::json bounceNames = nlohmann::json::array();
  ImageRgb runningSum(camera.width, camera.height);
  for (size_t k = 0; k < bounceImages.size(); ++k) {
    for (size_t p = 0; p < runningSum.pixels.size(); ++p)
      runningSum.pixels[p] += bounceImages[k].pixels[p];
    for (const auto& [stem, image] :
         {std::pair<std::string, const ImageRgb*>{"bounce_", &bounceImages[k]},
          {"bounce_sum_", &runningSum}}) {
      const std::string name = stem + std::to_string(k);
      bounceFiles.push_back(std::make_unique<AtomicPath>((dir / (name + ".exr")).string()));
      writeExr(bounceFiles.back()->tempPath(), *image);
      bounceFiles.push_back(std::make_unique<AtomicPath>((dir / (name + ".png")).string()));
      writePng(bounceFiles.back()->tempPath(), *image, toneMap);
      bounceNames.push_back(name);
    }
  }
  Rgb mean;
  for (const Rgb& p : render.image.pixels) mean += p;
  mean = mean / static_cast<double>(render.image.pixels.size());
  const double outputSeconds = secondsSince(t);
  const double totalSeconds = secondsSince(start);

  nlohmann::json report = {
      {"scene", o.solve.scenePath},
      {"method", method.name},
      // The light paths this image holds: the method's, or those --paths kept.
      {"paths", o.paths.empty() ? method.paths : o.paths},
      {"integrator", integrator->name()},
      {"camera",
       {{"position", vectorJson(camera.position)},
        {"look_at", vectorJson(camera.lookAt)},
        {"up", vectorJson(camera.up)},
        {"vfov_degrees", camera.vfovDegrees},
        {"width", camera.width},
        {"height", camera.height},
        {"lens_radius", camera.lensRadius},
        {"focus_distance", camera.focusDistance}}},
      {"samples_per_pixel", spp},
      {"adaptive", adaptiveReport(render, spp, settings.adaptive)},
      {"gather_rays", radiosity ? o.gather : 0},
      {"light_rays", radiosity ? (o.lightRays > 0 ? o.lightRays : o.gather) : 0},
      {"seed", o.solve.seed},
      {"threads", threads},
      {"rays",
       {{"camera", render.rays.camera},
        {"closest_hit", render.rays.closest},
        {"shadow", render.rays.shadow},
        {"total", render.rays.total()}}},
      {"rays_per_second", render.seconds > 0 ? render.rays.total() / render.seconds : 0.0},
      {"time_seconds",
       {{"solve", solveSeconds},
        {"bvh", bvhSeconds},
        {"render", render.seconds},
        {"output", outputSeconds},
        {"total", totalSeconds}}},
      {"mean_radiance", {mean.r, mean.g, mean.b}},
      {"units", "render.exr holds linear radiance, W/(m^2 sr), for scenes in metres"},
      {"tone_map",
       {{"exposure", toneMap.exposure},
        {"operator",
         "png = sRGB OETF(clamp(exposure * L, 0, 1)); exposure maps the 99th "
         "percentile of pixel luminance to 1 unless --exposure is given"}}},
      {"skipped", skipped},
  };
  {
    // The noise of render.exr: mean over pixels and channels of the variance of a pixel's mean.
    double variance = 0;
    for (const Rgb& v : render.variance.pixels) variance += v.sum();
    report["mean_pixel_variance"] = variance / (3.0 * render.variance.pixels.size());
  }
  if (o.method == "bdpt") report["mis"] = o.mis;
  if (separateBounces) {
    report["bounces_separate"] = {
        {"max_bounce", *o.bouncesSeparate},
        {"images", bounceNames},
        {"term", radiosity
                     ? "bounce_k: (rho F)^k E of Jacobi radiosity, shown as interpolated B_k/pi"
                     : "bounce_k: paths with exactly k scattering vertices (D or S): T^k L_e"}};
  }
  if (radiosity)
    report["radiosity"] = {{"elements", mesh.elementCount()},
                           {"solver", world.solved()->report.solverName},
                           {"converged", world.solved()->report.converged},
                           {"reused_saved_solution", world.reusedSolution()},
                           {"form_factor_rays", world.solved()->report.raysCast}};
  if (method.usesMotion && !world.motionSpec().empty())
    report["motion_blur"] = {
        {"shutter", {world.motionSpec().shutterOpen, world.motionSpec().shutterClose}},
        {"moving_objects", world.motionSpec().objects.size()}};
  AtomicFile json((dir / "render.json").string());
  json.stream() << report.dump(2) << "\n";

  // The solution, for the next render into this directory (not when it was reused from here).
  std::vector<AtomicFile*> files = {&json};
  std::unique_ptr<AtomicFile> solutionCsv, solutionJson;
  if (radiosity && !world.reusedSolution() && solutionIsReusable(o.solve)) {
    solutionCsv = std::make_unique<AtomicFile>((dir / kSolutionCsv).string());
    solutionJson = std::make_unique<AtomicFile>((dir / kSolutionJson).string());
    writeSavedSolution(*solutionCsv, *solutionJson, *world.solved(), o.solve);
    files.push_back(solutionCsv.get());
    files.push_back(solutionJson.get());
  }
  for (AtomicFile* f : files) f->finish();
  exr.commit();
  png.commit();
  for (auto& file : bounceFiles) file->commit();
  commitAll(files);
  logInfo("wrote render.exr, render.png, render.json to " + o.solve.outputDir + " (" +
          std::to_string(render.rays.total()) + " rays in " + std::to_string(render.seconds) +
          " s)");
}

}  // namespace

void registerRenderCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render an image from the scene's camera");
  cmd->add_option("scene", o->solve.scenePath, "OBJ scene file; camera from <scene>.camera.json")
      ->required();
  cmd->add_option("--out", o->solve.outputDir, "Output directory for render.exr/.png/.json")
      ->required();
  cmd->add_option("--method", o->method, renderMethodHelp())->default_val("radiosity");
  cmd->add_option("--paths", o->paths,
                  "path and bdpt: keep only light paths matching a Heckbert expression over "
                  "L D S E with * + ? | ( ), written light to eye (e.g. LS+DE: caustics)");
  cmd->add_option("--bounces-separate", o->bouncesSeparate,
                  "Also write bounce_k.exr/.png (the Neumann term T^k L_e) and bounce_sum_k "
                  "(terms 0..k) for k = 0..K (path, bdpt; radiosity: Jacobi iterates)");
  cmd->add_option("--mis", o->mis, "bdpt: multiple importance sampling heuristic, power | balance")
      ->default_val(o->mis);
  cmd->add_option(
         "--gather", o->gather,
         "Final-gather rays (and shadow rays) per diffuse eye hit; 0: interpolated preview, or "
         "with --light-rays N, direct light by N shadow rays and the solution's indirect light")
      ->default_val(o->gather);
  cmd->add_option(
         "--light-rays", o->lightRays,
         "Shadow rays to the emitters per diffuse eye hit of the final gather, MIS-weighted "
         "against the --gather rays by their counts; 0: as many as --gather; with --gather 0: "
         "the direct light by these rays alone, the indirect light interpolated from the solution")
      ->default_val(o->lightRays);
  cmd->add_option("--spp", o->spp, "Samples per pixel (default: the method's, see --method)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--adaptive", o->adaptive,
                "Adaptive pixel sampling: --spp is the mean per pixel; a quarter of it in every "
                "pixel, the rest shared out in proportion to the spread of the neighbours' samples "
                "(lights' outlines, shadow edges, noisy gathers); from --spp 8");
  cmd->add_option("--camera", o->cameraFile, "Camera JSON file (default: <scene>.camera.json)");
  cmd->add_option("--position", o->position, "Camera position x y z")->expected(3);
  cmd->add_option("--look-at", o->lookAt, "Point the camera looks at, x y z")->expected(3);
  cmd->add_option("--up", o->up, "Camera up vector x y z")->expected(3);
  cmd->add_option("--vfov", o->vfov, "Vertical field of view, degrees");
  cmd->add_option("--width", o->width, "Image width in pixels");
  cmd->add_option("--height", o->height, "Image height in pixels");
  cmd->add_option("--lens-radius", o->lensRadius, "Thin-lens aperture radius (0: pinhole)");
  cmd->add_option("--focus-distance", o->focusDistance, "Distance to the plane in focus");
  cmd->add_option("--exposure", o->exposure,
                  "PNG exposure (default: 99th percentile of luminance maps to 1)");
  cmd->add_flag("--fresh-solve", o->freshSolve,
                "Solve even when --out holds a solution saved by an earlier render of the same "
                "scene and solve options (otherwise it is reused)");
  cmd->add_option("--solution", o->solutionDir,
                  "Reuse the solution `radiosity solve` (or an earlier render) saved in this "
                  "directory; an error when it was made from another scene or other solve options")
      ->excludes("--fresh-solve");
  addSolveOptions(*cmd, o->solve, o->solverName);
  addCommonFlags(*cmd);
  cmd->callback([&run, cmd, o] { run = [cmd, o] { runRender(*cmd, *o); }; });
}

}  // namespace rad
