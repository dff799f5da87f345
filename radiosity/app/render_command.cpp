// `radiosity render SCENE.obj --out DIR`: images from the scene's camera by one of the methods of
// render_methods.h (final gather over the radiosity solution, path tracing, the classic ones).
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "radiosity/app/commands.h"
#include "radiosity/app/render_methods.h"
#include "radiosity/app/render_world.h"
#include "radiosity/app/solve_job.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/output/image_io.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/image_renderer.h"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct RenderCommandOptions {
  SolveOptions solve;
  std::string solverName = "progressive";
  std::string method = "radiosity";
  int gather = 64;
  int spp = 0;  // 0: the method's default
  std::string cameraFile;
  std::vector<double> position, lookAt, up;
  std::optional<double> vfov, lensRadius, focusDistance, exposure;
  std::optional<int> width, height;
};

Eigen::Vector3d toVector(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// The camera from --camera, the scene's sidecar or the command line; `source` gets the file it
// came from ("" for none), which also holds the motion-blur fields.
Camera resolveCamera(const RenderCommandOptions& o, std::string& source) {
  Camera camera;
  source = o.cameraFile;
  if (source.empty()) {
    const std::string sidecar = cameraSidecarPath(o.solve.scenePath);
    if (std::filesystem::exists(sidecar)) source = sidecar;
  }
  if (!source.empty()) {
    camera = loadCamera(source);
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

void runRender(RenderCommandOptions& o) {
  const auto start = Clock::now();
  const RenderMethod& method = findRenderMethod(o.method);
  if (o.gather < 0) throw InputError("--gather must be >= 0");
  if (o.spp < 0) throw InputError("--spp must be >= 1");
  if (o.exposure && !(*o.exposure > 0)) throw InputError("--exposure must be > 0");
  const bool radiosity = method.needsSolve;
  const int spp = o.spp > 0 ? o.spp : method.defaultSpp;
  o.solve.solver = parseSolverKind(o.solverName);
  std::string cameraSource;
  // Before any long work: a bad camera or motion description fails at once.
  const Camera camera = resolveCamera(o, cameraSource);
  RenderWorld world(o.solve, cameraSource);

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

  std::unique_ptr<Integrator> integrator =
      method.makeIntegrator(MethodInputs{renderScene, view.radiosity, o.gather});
  if (radiosity && o.gather == 0)
    skip("final gather", "--gather 0: interpolated radiosity preview");
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.seed = o.solve.seed;
  const RenderOutput render = renderImage(camera, *integrator, settings);
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
  const ToneMap toneMap =
      o.exposure ? ToneMap{*o.exposure} : ToneMap::autoExposure(render.image.pixels, {});
  AtomicPath exr((dir / "render.exr").string());
  writeExr(exr.tempPath(), render.image);
  AtomicPath png((dir / "render.png").string());
  writePng(png.tempPath(), render.image, toneMap);
  Rgb mean;
  for (const Rgb& p : render.image.pixels) mean += p;
  mean = mean / static_cast<double>(render.image.pixels.size());
  const double outputSeconds = since(t);
  const double totalSeconds = since(start);

  nlohmann::json report = {
      {"scene", o.solve.scenePath},
      {"method", method.name},
      {"paths", method.paths},
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
      {"gather_rays", radiosity ? o.gather : 0},
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
  if (radiosity)
    report["radiosity"] = {{"elements", mesh.elementCount()},
                           {"solver", world.solved()->solverName},
                           {"converged", world.solved()->converged},
                           {"form_factor_rays", world.solved()->raysCast}};
  if (method.usesMotion && !world.motionSpec().empty())
    report["motion_blur"] = {
        {"shutter", {world.motionSpec().shutterOpen, world.motionSpec().shutterClose}},
        {"moving_objects", world.motionSpec().objects.size()}};
  AtomicFile json((dir / "render.json").string());
  json.stream() << report.dump(2) << "\n";

  exr.commit();
  png.commit();
  json.commit();
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
  cmd->add_option(
         "--gather", o->gather,
         "Final-gather rays (and shadow rays) per diffuse eye hit; 0: interpolated preview")
      ->default_val(o->gather);
  cmd->add_option("--spp", o->spp, "Samples per pixel (default: the method's, see --method)")
      ->check(CLI::PositiveNumber);
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
  addSolveOptions(*cmd, o->solve, o->solverName);
  addCommonFlags(*cmd);
  cmd->callback([&run, o] { run = [o] { runRender(*o); }; });
}

}  // namespace rad
