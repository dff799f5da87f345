// `radiosity render SCENE.obj --out DIR`: images from the scene's camera by one of the methods of
// render_methods.h (final gather over the radiosity solution, path tracing, the classic ones).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

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
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/image_io.h"
#include "radiosity/pipeline/saved_solution.h"
#include "radiosity/pipeline/thread_limit.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/exposure_weights.h"
#include "radiosity/render/image_renderer.h"
#include "radiosity/render/interpolated_preview.h"
#include "radiosity/render/path_expression.h"
#include "radiosity/render/path_renderer.h"
#include "radiosity/render/render_methods.h"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;

struct RenderCommandOptions {
  SolveOptions solve;
  std::string method = "radiosity";
  FinalGatherOptions gather = {kRenderGather, 0};  // radiosity: --gather, --light-rays
  int spp = 0;                                     // 0: the method's default
  bool adaptive = false;  // --adaptive: spp is the mean, shared out by the pixels' spread
  CameraOptions camera;
  ExposureOption exposure;
  bool freshSolve = false;             // solve even when --out holds a reusable solution
  std::string solutionDir;             // --solution: reuse the solution `solve` saved there
  std::string paths;                   // --paths: Heckbert expression (path, bdpt)
  std::optional<int> bouncesSeparate;  // --bounces-separate K
  std::string mis = "power";           // --mis (bdpt), a name of misHeuristicTable()
};

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

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// The methods that follow whole light paths per pixel (the path renderer): they bin paths by
// type or bounce (--paths, --bounces-separate), and have no per-pixel second pass (--adaptive).
bool followsWholePaths(const RenderMethod& method) {
  return method.name == "path" || method.name == "bdpt";
}

// Every option render's method does not use, given, is an error saying why; so are values no
// method can use. For --method radiosity --bounces-separate K, the solve becomes Jacobi's K
// bounces (its iterates are the Neumann terms). Before any long work.
void checkRenderOptions(const CLI::App& command, RenderCommandOptions& o,
                        const RenderMethod& method) {
  const std::string byMethod = "--method " + method.name;
  const bool wholePaths = followsWholePaths(method);
  if (wasGiven(command, "--paths") && !wholePaths)
    throw InputError("--paths needs --method path or bdpt (" + byMethod +
                     " does not follow light paths one by one)");
  if (o.bouncesSeparate && !wholePaths && !method.needsSolve)
    throw InputError("--bounces-separate needs --method path, bdpt or radiosity (" + byMethod +
                     " does not sum a Neumann series)");
  if (o.bouncesSeparate && *o.bouncesSeparate < 0)
    throw InputError("--bounces-separate must be >= 0 (the highest Neumann term to write)");
  if (wasGiven(command, "--paths") && o.bouncesSeparate)
    throw InputError("--paths and --bounces-separate cannot be combined: give one of them");
  parseName(misHeuristicTable(), o.mis, "--mis");
  if (method.name != "bdpt")
    refuseIfGiven(command, "--mis",
                  "--mis applies to --method bdpt only (it weighs the ways bdpt joins eye and "
                  "light sub-paths)");
  if (wasGiven(command, "--adaptive") && wholePaths)
    throw InputError("--adaptive: " + byMethod +
                     " is not sampled adaptively; use it with radiosity, direct, whitted or "
                     "distribution");
  checkGatherOptions(o.gather);
  o.exposure.check();
  if (o.bouncesSeparate && wasGiven(command, "--bounces"))
    throw InputError("--bounces-separate K sets the Jacobi bounces itself: leave out --bounces");
  if (!method.needsSolve) {
    const std::string why = byMethod + " does not solve radiosity";
    refuseGatherOptions(command, why + ": there is no solution to gather from");
    for (const char* name : {"--solution", "--fresh-solve"}) refuseIfGiven(command, name, why);
    finishWithoutSolve(command, o.solve, why);
    return;
  }
  if (o.bouncesSeparate) {
    // The Neumann terms are the Jacobi iterates: B_k − B_{k−1} = (ρF)^k E.
    if (wasGiven(command, "--solver") && o.solve.solver != SolverKind::Jacobi)
      throw InputError(
          "--bounces-separate with --method radiosity runs --solver jacobi (its iterates "
          "are the Neumann terms); --solver " +
          solverKindName(o.solve.solver) + " cannot give them");
    o.solve.solver = SolverKind::Jacobi;
    o.solve.bounces = *o.bouncesSeparate;
    o.solve.keepBounceTerms = true;
  }
  finishSolveOptions(command, o.solve);
}

// Work a render skipped, with why: the log and render.json's "skipped".
class SkipList {
 public:
  void add(const std::string& what, const std::string& why) {
    logInfo("skipped: " + what + " (" + why + ")");
    json_.push_back({{"what", what}, {"why", why}});
  }
  void add(const std::vector<SkipNote>& notes) {
    for (const SkipNote& s : notes) json_.push_back({{"what", s.what}, {"why", s.why}});
  }
  const nlohmann::json& json() const { return json_; }

 private:
  nlohmann::json json_ = nlohmann::json::array();
};

// The image, and for --paths or --bounces-separate the images beside it (bounce_*.exr).
struct RenderedImages {
  RenderOutput render;
  std::vector<ImageRgb> bounces;
};

// Renders the image with the method's integrator: through the path binning for --paths and the
// path methods' --bounces-separate, else the image alone, with radiosity's Neumann terms each
// shown by its interpolated eye pass.
RenderedImages renderImages(const RenderCommandOptions& o, RenderWorld& world,
                            const RenderScene& renderScene, const Integrator& integrator,
                            const Camera& camera, const RenderSettings& settings,
                            const std::optional<ExpressionBinning>& pathFilter, bool radiosity,
                            SkipList& skipped) {
  RenderedImages out;
  const auto* pathIntegrator = dynamic_cast<const PathIntegrator*>(&integrator);
  if (pathIntegrator && (pathFilter || o.bouncesSeparate)) {
    std::optional<BounceBinning> bounceBins;
    if (o.bouncesSeparate) bounceBins.emplace(*o.bouncesSeparate);
    const PathBinning* binning = pathFilter   ? static_cast<const PathBinning*>(&*pathFilter)
                                 : bounceBins ? static_cast<const PathBinning*>(&*bounceBins)
                                              : nullptr;
    PathRenderOutput paths = renderPathImage(camera, *pathIntegrator, settings, binning);
    out.render = std::move(paths.full);
    if (pathFilter) {  // the main image holds the matching paths only
      out.render.image = std::move(paths.bins[0].image);
      out.render.variance = std::move(paths.bins[0].variance);
    }
    if (bounceBins)
      for (RenderOutput& bin : paths.bins) out.bounces.push_back(std::move(bin.image));
    return out;
  }
  out.render = renderMethodImage(camera, integrator, settings);
  if (o.bouncesSeparate && radiosity) {
    // The eye pass of each term: its interpolated B_k/π at the first diffuse hit (gather 0),
    // seen through mirrors and glass; linear in B, so the terms sum to the --gather 0 image.
    RenderSettings quiet = settings;
    quiet.showProgress = false;
    for (const std::vector<Rgb>& term : world.solved()->solution.bounceTerms) {
      const InterpolatedPreview eyePass(renderScene, term);
      out.bounces.push_back(renderImage(camera, eyePass, quiet).image);
    }
    if (o.gather.gatherRays > 0)
      skipped.add("final gather in the bounce_* images",
                  "each Neumann term is shown by the interpolated preview (--gather 0), which "
                  "they sum to");
  }
  return out;
}

// render.exr (linear radiance) and render.png (tone-mapped) under temporary names, and for each
// term k bounce_k (the term T^k L_e) and bounce_sum_k (the terms 0..k), the PNGs at the main
// exposure. Returns the bounce images' names; `files` takes the temporary files.
nlohmann::json writeImages(const std::filesystem::path& dir, const RenderedImages& images,
                           const Camera& camera, const ToneMap& toneMap,
                           std::vector<std::unique_ptr<AtomicPath>>& files) {
  auto add = [&](const std::string& name, const ImageRgb& image) {
    files.push_back(std::make_unique<AtomicPath>((dir / (name + ".exr")).string()));
    writeExr(files.back()->tempPath(), image);
    files.push_back(std::make_unique<AtomicPath>((dir / (name + ".png")).string()));
    writePng(files.back()->tempPath(), image, toneMap);
  };
  add("render", images.render.image);
  nlohmann::json names = nlohmann::json::array();
  ImageRgb runningSum(camera.width, camera.height);
  for (size_t k = 0; k < images.bounces.size(); ++k) {
    for (size_t p = 0; p < runningSum.pixels.size(); ++p)
      runningSum.pixels[p] += images.bounces[k].pixels[p];
    for (const auto& [stem, image] :
         {std::pair<std::string, const ImageRgb*>{"bounce_", &images.bounces[k]},
          {"bounce_sum_", &runningSum}}) {
      add(stem + std::to_string(k), *image);
      names.push_back(stem + std::to_string(k));
    }
  }
  return names;
}

// What render.json says beyond the images' own figures: the method and its paths, the camera,
// the sampling, rays and times, the mean radiance and its noise, what was skipped.
struct RenderFacts {
  const RenderMethod& method;
  const Integrator& integrator;
  const Camera& camera;
  const RenderSettings& settings;
  const RenderOutput& render;
  const ToneMap& toneMap;
  int elements = 0;  // of the mesh the image was rendered from
  int threads = 0;
  double solveSeconds = 0, bvhSeconds = 0, outputSeconds = 0, totalSeconds = 0;
};

nlohmann::json renderReport(const RenderCommandOptions& o, const RenderFacts& f,
                            const RenderWorld& world, const nlohmann::json& bounceNames,
                            const SkipList& skipped) {
  const bool radiosity = f.method.needsSolve;
  const Camera& camera = f.camera;
  const RenderOutput& render = f.render;
  const int spp = f.settings.samplesPerPixel;
  Rgb mean;
  for (const Rgb& p : render.image.pixels) mean += p;
  mean = mean / static_cast<double>(render.image.pixels.size());
  nlohmann::json report = {
      {"scene", o.solve.scenePath},
      {"method", f.method.name},
      // The light paths this image holds: the method's, or those --paths kept.
      {"paths", o.paths.empty() ? f.method.paths : o.paths},
      {"integrator", f.integrator.name()},
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
      {"adaptive", adaptiveReport(render, spp, f.settings.adaptive)},
      {"gather_rays", radiosity ? o.gather.gatherRays : 0},
      {"light_rays", radiosity ? o.gather.shadowRays() : 0},
      {"seed", o.solve.seed},
      {"threads", f.threads},
      {"rays",
       {{"camera", render.rays.camera},
        {"closest_hit", render.rays.closest},
        {"shadow", render.rays.shadow},
        {"total", render.rays.total()}}},
      {"rays_per_second", render.seconds > 0 ? render.rays.total() / render.seconds : 0.0},
      {"time_seconds",
       {{"solve", f.solveSeconds},
        {"bvh", f.bvhSeconds},
        {"render", render.seconds},
        {"output", f.outputSeconds},
        {"total", f.totalSeconds}}},
      {"mean_radiance", {mean.r, mean.g, mean.b}},
      {"units", "render.exr holds linear radiance, W/(m^2 sr), for scenes in metres"},
      {"tone_map",
       {{"exposure", f.toneMap.exposure},
        {"operator",
         "png = sRGB OETF(clamp(exposure * L, 0, 1)); exposure maps the 99th "
         "percentile of pixel luminance to 1 unless --exposure is given"}}},
      {"skipped", skipped.json()},
  };
  {
    // The noise of render.exr: mean over pixels and channels of the variance of a pixel's mean.
    double variance = 0;
    for (const Rgb& v : render.variance.pixels) variance += v.sum();
    report["mean_pixel_variance"] = variance / (3.0 * render.variance.pixels.size());
  }
  if (o.method == "bdpt") report["mis"] = o.mis;
  if (o.bouncesSeparate) {
    report["bounces_separate"] = {
        {"max_bounce", *o.bouncesSeparate},
        {"images", bounceNames},
        {"term", radiosity
                     ? "bounce_k: (rho F)^k E of Jacobi radiosity, shown as interpolated B_k/pi"
                     : "bounce_k: paths with exactly k scattering vertices (D or S): T^k L_e"}};
  }
  if (radiosity)
    report["radiosity"] = {{"elements", f.elements},
                           {"solver", world.solved()->report.solverName},
                           {"converged", world.solved()->report.converged},
                           {"reused_saved_solution", world.reusedSolution()},
                           {"form_factor_rays", world.solved()->report.raysCast}};
  if (f.method.usesMotion && !world.motionSpec().empty())
    report["motion_blur"] = {
        {"shutter", {world.motionSpec().shutterOpen, world.motionSpec().shutterClose}},
        {"moving_objects", world.motionSpec().objects.size()}};
  return report;
}

// What the render command skips before it renders, and why.
void noteSkippedWork(const RenderCommandOptions& o, const RenderWorld& world,
                     const RenderScene& renderScene, const Camera& camera, bool radiosity,
                     SkipList& skipped) {
  skipped.add(world.skipped());
  if (!renderScene.hasSpecular())
    skipped.add("specular branch", "the scene has no mirror or glass material");
  if (radiosity && o.gather.gatherRays == 0)
    skipped.add("final gather",
                o.gather.indirectFromSolution()
                    ? "--gather 0 --light-rays N: the indirect light is the solution's"
                    : "--gather 0: interpolated radiosity preview");
  if (o.method == "bdpt" && camera.lensRadius > 0)
    skipped.add("light tracing (t = 1)", "it needs a pinhole camera (lens radius 0)");
}

RenderSettings renderSettings(const RenderCommandOptions& o, const RenderMethod& method) {
  RenderSettings settings;
  settings.samplesPerPixel = o.spp > 0 ? o.spp : method.defaultSpp;
  settings.adaptive = o.adaptive;
  settings.seed = o.solve.seed;
  return settings;
}

// The solution, for the next render into `dir` (not when it was reused from there, nor when it
// cannot be reused): its two files, owned by `owned`, listed in `files` to take their names with
// the render's.
void keepSolutionForNextRender(const RenderCommandOptions& o, const RenderWorld& world,
                               const std::filesystem::path& dir,
                               std::vector<std::unique_ptr<AtomicFile>>& owned,
                               std::vector<AtomicFile*>& files) {
  if (world.reusedSolution() || !solutionIsReusable(o.solve)) return;
  owned.push_back(std::make_unique<AtomicFile>((dir / kSolutionCsv).string()));
  owned.push_back(std::make_unique<AtomicFile>((dir / kSolutionJson).string()));
  writeSavedSolution(*owned[0], *owned[1], *world.solved(), o.solve);
  files.push_back(owned[0].get());
  files.push_back(owned[1].get());
}

void runRender(const CLI::App& command, RenderCommandOptions& o) {
  const auto start = Clock::now();
  const RenderMethod& method = findRenderMethod(o.method);
  checkRenderOptions(command, o, method);
  // The path expression and the camera before any long work: a bad one fails at once.
  std::optional<ExpressionBinning> pathFilter;
  if (!o.paths.empty()) pathFilter.emplace(PathExpression::parse(o.paths));
  const ResolvedCamera resolved = resolveCamera(o.camera, o.solve.scenePath);
  const Camera& camera = resolved.camera;
  RenderWorld world(o.solve, resolved.file,
                    {o.solutionDir, o.freshSolve ? std::string() : o.solve.outputDir,
                     o.gather.indirectFromSolution()});
  const ThreadLimit threadLimit(o.solve.threads);

  // The scene, its mesh and BVH, and (for methods that need it) the radiosity solution.
  const RenderWorld::View view = world.viewFor(method);
  const RenderScene& renderScene = *view.scene;
  SkipList skipped;
  noteSkippedWork(o, world, renderScene, camera, method.needsSolve, skipped);
  const std::unique_ptr<Integrator> integrator = method.makeIntegrator(
      MethodInputs{renderScene, view.radiosity, view.directIrradiance, o.gather, &camera,
                   parseName(misHeuristicTable(), o.mis, "--mis")});
  const RenderSettings settings = renderSettings(o, method);
  const RenderedImages images = renderImages(o, world, renderScene, *integrator, camera, settings,
                                             pathFilter, method.needsSolve, skipped);
  const RenderOutput& render = images.render;
  if (render.rays.gathersSkipped > 0)
    skipped.add("gathers at " + std::to_string(render.rays.gathersSkipped) + " eye-ray hits",
                "the surface hit reflects nothing (ρ = 0): its radiance is its Ke");

  // Outputs: EXR (linear radiance), PNG (tone-mapped), JSON (report); renamed together at the end.
  const auto t = Clock::now();
  throwIfInterrupted();
  OutputSection writing;  // Ctrl-C now waits until every file has its final name (or none has)
  ensureDirectory(o.solve.outputDir);
  const std::filesystem::path dir(o.solve.outputDir);
  // Auto exposure from the lit surfaces in view: emitter and sky pixels do not set it.
  const ToneMap toneMap = o.exposure.toneMap([&] {
    return ToneMap::autoExposure(render.image.pixels, exposureWeights(camera, renderScene));
  });
  std::vector<std::unique_ptr<AtomicPath>> imageFiles;
  const nlohmann::json bounceNames = writeImages(dir, images, camera, toneMap, imageFiles);
  const RenderFacts facts{method,
                          *integrator,
                          camera,
                          settings,
                          render,
                          toneMap,
                          renderScene.mesh().elementCount(),
                          threadLimit.threads(),
                          world.solveSeconds(),
                          world.bvhSeconds(),
                          secondsSince(t),
                          secondsSince(start)};
  AtomicFile json((dir / "render.json").string());
  json.stream() << renderReport(o, facts, world, bounceNames, skipped).dump(2) << "\n";

  std::vector<AtomicFile*> files = {&json};
  std::vector<std::unique_ptr<AtomicFile>> solutionFiles;
  if (method.needsSolve) keepSolutionForNextRender(o, world, dir, solutionFiles, files);
  for (AtomicFile* f : files) f->finish();
  for (auto& file : imageFiles) file->commit();
  commitAll(files);
  logInfo("wrote render.exr, render.png, render.json to " + o.solve.outputDir + " (" +
          std::to_string(render.rays.total()) + " rays in " + std::to_string(render.seconds) +
          " s)");
}

}  // namespace

void registerRenderCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render an image from the scene's camera");
  cmd->add_option("scene", o->solve.scenePath,
                  std::string(kSceneFileHelp) + "; camera from <scene>.camera.json")
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
  cmd->add_option(
         "--mis", o->mis,
         "bdpt: multiple importance sampling heuristic: " + joinTableNames(misHeuristicTable()))
      ->default_val(o->mis);
  addGatherOptions(*cmd, o->gather, "diffuse eye hit (radiosity)");
  cmd->add_option("--spp", o->spp, "Samples per pixel (default: the method's, see --method)")
      ->check(positiveNumber());
  cmd->add_flag("--adaptive", o->adaptive,
                "Adaptive pixel sampling: --spp is the mean per pixel; a quarter of it in every "
                "pixel, the rest shared out in proportion to the spread of the neighbours' samples "
                "(lights' outlines, shadow edges, noisy gathers); from --spp 8");
  addCameraOptions(*cmd, o->camera, CameraOverrides::All);
  o->exposure.add(*cmd, "PNG exposure (default: 99th percentile of luminance maps to 1)");
  cmd->add_flag("--fresh-solve", o->freshSolve,
                "Solve even when --out holds a solution saved by an earlier render of the same "
                "scene and solve options (otherwise it is reused)");
  cmd->add_option("--solution", o->solutionDir,
                  "Reuse the solution `radiosity solve` (or an earlier render) saved in this "
                  "directory; an error when it was made from another scene or other solve options")
      ->excludes("--fresh-solve");
  addSolveOptions(*cmd, o->solve);
  addCommonFlags(*cmd);
  cmd->callback([&run, cmd, o] { run = [cmd, o] { runRender(*cmd, *o); }; });
}

}  // namespace rad
