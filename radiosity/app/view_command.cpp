// `radiosity view SCENE.obj | DIR`: the solution in a VTK window (or a PNG with --screenshot),
// and the solver behind it, which the viewer's keys step live.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <regex>

#include "radiosity/app/commands.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/options/solve_option_group.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/output/display_radiance.h"
#include "radiosity/pipeline/form_factor_stage.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/solution_source.h"
#include "radiosity/pipeline/solution_tone_map.h"
#include "radiosity/render/light_probes.h"
#include "radiosity/scene/camera.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/solvers/solver_factory.h"
#include "radiosity/visibility/ray_caster.h"
#include "viewer/display_scalars.h"
#include "viewer/solution_polydata.h"
#include "viewer/solution_viewer.h"
#include "viewer/solution_vtp.h"

namespace rad {
namespace {

// The solver of a finished solve, built again over its mesh and problem by the same stages
// solveScene uses, so the viewer can replay and step it. Rows are cached, so restarting costs no
// rays.
class ViewerSolve final : public LiveSolution {
 public:
  ViewerSolve(const Solution& solution, const SolveOptions& options)
      : solution_(solution),
        kind_(options.solver),
        rays_(*solution.mesh, solution.scene),
        formFactors_(solution.scene, *solution.mesh, rays_, solution.problem, options),
        limits_(iterationLimits(options, solution.mesh->elementCount(),
                                std::chrono::steady_clock::now())) {
    limits_.timeLimit = 0;  // the viewer steps on request, without a clock
    if (needsGatheringMatrix(kind_)) gather_ = formFactors_.gatheringMatrix();
    restart();
  }

  std::vector<Rgb> radiosity(bool withAmbient) const override {
    const auto* shooting = dynamic_cast<const ProgressiveSolver*>(solver_.get());
    return withAmbient && shooting ? shooting->withAmbient() : solver_->solution();
  }
  std::vector<Rgb> unshot() const override {
    const auto* shooting = dynamic_cast<const ProgressiveSolver*>(solver_.get());
    return shooting ? shooting->unshotPowerOfElements()
                    : std::vector<Rgb>(solution_.problem.size());
  }
  void step() override {
    if (converged()) return;
    solver_->step();
    history_.push_back(solver_->progress());
  }
  void restart() override {
    solver_ = makeSolver(kind_, solution_.problem, formFactors_.shots(), [&] { return gather_; });
    history_ = {solver_->progress()};
  }
  bool converged() const override {
    return solver_->iterations() >= limits_.maxIterations ||
           solver_->progress() <= limits_.tolerance;
  }
  int iterations() const override { return solver_->iterations(); }
  const std::vector<double>& history() const override { return history_; }
  std::string measure() const override { return solver_->progressMeasure(); }
  std::string solverName() const override { return solver_->name(); }
  int lastShooter() const override {
    // Shooters are elements only for hemisphere rows; analytic shooters are whole patches.
    const auto* shooting = dynamic_cast<const ProgressiveSolver*>(solver_.get());
    return shooting && !formFactors_.analytic() ? shooting->lastShooter() : -1;
  }
  // The element's hemisphere row (with the analytic method, the rays the hemisphere method would
  // cast: that method uses shadow rays to patches instead).
  std::vector<RaySegment> rowRays(int element) const override {
    const double escapeLength = 0.25 * solution_.mesh->boundsDiagonal();
    std::vector<RaySegment> out;
    for (const RowRay& r : formFactors_.hemisphere().traceRow(element)) {
      const double length = std::isfinite(r.distance) ? r.distance : escapeLength;
      out.push_back({r.origin, r.origin + length * r.direction, r.target >= 0});
    }
    return out;
  }
  double tolerance() const { return limits_.tolerance; }

 private:
  const Solution& solution_;
  SolverKind kind_;
  RayCaster rays_;
  FormFactorStage formFactors_;
  IterationLimits limits_;
  SparseRows gather_;
  std::unique_ptr<Solver> solver_;
  std::vector<double> history_;
};

struct ViewArgs {
  std::string input, screenshot, size = "1280x720", scalar = "colour";
  bool cameraFromScene = false, smooth = false, edges = false, outlines = false, noChart = false;
  bool noHelp = false;
  int raysOf = -1;
  int stopAfter = -1;
  std::string solutionDir;  // --solution: show the solution `solve` saved there
  std::string probes;       // --probes FILE: a probes.bin to show
  bool noProbes = false;
};

// The light probes to show: --probes FILE, else DIR/probes.bin when the solution directory (view
// DIR, or --solution DIR) has one; none with --no-probes. A bad file is an InputError naming it.
std::vector<ProbeSh> loadViewProbes(const ViewArgs& args, const std::string& solutionDir) {
  if (args.noProbes) return {};
  std::string path = args.probes;
  if (path.empty() && !solutionDir.empty()) {
    const std::filesystem::path inDir = std::filesystem::path(solutionDir) / "probes.bin";
    if (std::filesystem::is_regular_file(inDir)) path = inDir.string();
  }
  if (path.empty()) return {};
  std::vector<ProbeSh> probes = readProbesBinary(path);
  int inside = 0;
  for (const ProbeSh& p : probes) inside += p.inside;
  logInfo("light probes: " + std::to_string(probes.size()) + " from " + path + " (" +
          std::to_string(inside) + " inside geometry, hidden; key i toggles them)");
  return probes;
}

void parseSize(const std::string& text, ViewerOptions& view) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
    throw InputError("--size '" + text + "': expected WIDTHxHEIGHT, e.g. 1280x720");
  view.width = std::stoi(m[1]);
  view.height = std::stoi(m[2]);
  if (view.width < 64 || view.height < 64 || view.width > 8192 || view.height > 8192)
    throw InputError("--size '" + text + "': width and height must lie in [64, 8192]");
}

void requireDisplay(bool screenshot) {
  const char* display = std::getenv("DISPLAY");
  if (display && *display) return;
  // Debian's VTK renders through X only, off-screen included.
  throw RuntimeFailure(screenshot
                           ? "no X display for off-screen rendering (this VTK build needs one): "
                             "run under `xvfb-run -a radiosity view ...`"
                           : "no X display (DISPLAY is not set): run on a desktop, or use "
                             "--screenshot FILE.png under `xvfb-run -a`");
}

// An element's links as the viewer draws them, each with its share of the light they bring.
LinksOfElement linksForViewer(std::shared_ptr<const ElementLinks> links) {
  return [links](int element) {
    std::vector<LinkSegment> out;
    double total = 0;
    for (const ElementLink& l : links->of(element)) {
      LinkSegment s;
      s.from = l.receiverCentroid.cast<double>();
      s.to = l.sourceCentroid.cast<double>();
      s.cluster = l.sourceIsCluster;
      s.share = l.irradiance.luminance();
      total += s.share;
      out.push_back(s);
    }
    for (LinkSegment& s : out) s.share = total > 0 ? s.share / total : 0.0;
    return out;
  };
}

// Every view option the input does not use, given, is an error saying why. `savedVtp`: the input
// is a directory holding solution.vtp (no scene, no solver); otherwise `options` is the solve's.
void checkViewOptions(const CLI::App& command, const ViewArgs& args, bool savedVtp,
                      const SolveOptions& options) {
  if (!args.screenshot.empty())
    refuseIfGiven(command, "--no-help", "--screenshot draws no key overlay");
  if (savedVtp) {
    const std::string why = "a saved solution.vtp (view DIR) is shown as it was solved";
    refuseAllSolveOptions(command, why);
    refuseIfGiven(command, "--solution",
                  args.input +
                      " is already a solution directory (view SCENE --solution DIR shows a "
                      "saved solve over its scene)");
    refuseIfGiven(command, "--rays-of",
                  "a saved solution.vtp has no form factors; open the scene to see rays");
    refuseIfGiven(command, "--stop-after", "a saved solution.vtp has no solver to step");
    refuseIfGiven(command, "--no-chart", "a saved solution.vtp has no iterations to chart");
    return;
  }
  finishSolveOptions(command, options);
  if (options.solver == SolverKind::Hierarchical) {
    refuseIfGiven(command, "--stop-after", "the hierarchical solve is not stepped live");
    refuseIfGiven(command, "--no-chart", "the hierarchical solve is shown without a chart");
    if (!args.solutionDir.empty())
      refuseIfGiven(command, "--rays-of",
                    "a reused hierarchical solution (--solution) keeps no links to draw");
  } else if (!args.solutionDir.empty()) {
    refuseIfGiven(command, "--no-chart",
                  "a reused solution (--solution) has no iterations to replay for a chart");
  }
}

void runView(const ViewArgs& args, SolveOptions options, const CLI::App& command) {
  const bool savedVtp = std::filesystem::is_directory(args.input);
  options.scenePath = args.input;
  checkViewOptions(command, args, savedVtp, options);
  ViewerOptions view;
  parseSize(args.size, view);
  view.scalar = parseDisplayScalar(args.scalar);
  view.smooth = args.smooth;
  view.edges = args.edges;
  view.outlines = args.outlines;
  view.chart = !args.noChart;
  view.help = !args.noHelp && args.screenshot.empty();
  view.pickElement = args.raysOf;
  view.stopAfter = args.stopAfter;
  view.title = "radiosity view " + args.input;
  requireDisplay(!args.screenshot.empty());

  std::vector<ProbeSh> probes;
  auto show = [&](vtkSmartPointer<vtkPolyData> data, ToneMap toneMap, LiveSolution* live) {
    SolutionViewer viewer(std::move(data), toneMap, live, view);
    if (!probes.empty()) viewer.setProbes(probes);
    if (!args.screenshot.empty())
      viewer.screenshot(args.screenshot);
    else
      viewer.interact();
  };
  auto cameraFor = [&](const std::string& scenePath) {
    if (!args.cameraFromScene) return;
    view.camera = findSceneCamera(scenePath);
    if (!view.camera) logInfo("no " + cameraSidecarPath(scenePath) + ": framing the bounding box");
  };

  if (savedVtp) {
    const std::string path = (std::filesystem::path(args.input) / "solution.vtp").string();
    vtkSmartPointer<vtkPolyData> data = readSolutionVtp(path);
    probes = loadViewProbes(args, args.input);
    cameraFor(solutionSceneFile(data));
    view.pickElement = -1;
    const ToneMap toneMap = solutionToneMap(data);
    show(data, toneMap, nullptr);
    return;
  }

  options.keepLinks = options.solver == SolverKind::Hierarchical;  // what picking draws
  probes = loadViewProbes(args, args.solutionDir);  // before the solve: a bad file fails at once
  const SolveResult result = solveOrReuse(
      loadScene(options.scenePath, options.lights, options.twoSided, options.unreadableTextures),
      options, {args.solutionDir, ""});
  const Solution& solution = result.solution;
  cameraFor(options.scenePath);
  const ToneMap toneMap = solutionToneMap(solution);
  vtkSmartPointer<vtkPolyData> data =
      makeSolutionPolyData(*solution.mesh, solution.radiosity, solution.unshot, toneMap);

  if (options.solver == SolverKind::Hierarchical) {
    // The viewer shows the result and, picked, an element's links; it does not step the solve.
    // A reused solution keeps no links (checkViewOptions refuses --rays-of then).
    if (solution.links)
      view.linksOf = linksForViewer(solution.links);
    else
      view.pickElement = -1;
    view.chart = false;
    show(data, toneMap, nullptr);
    return;
  }
  ViewerSolve live(solution, options);
  view.tolerance = live.tolerance();
  // Replay the solve to draw its convergence curve (rows are recomputed once, then cached):
  // the result is the same solution, deterministic for the seed. Not for a reused solution:
  // that would cast the very rays reusing it saves (the keys still step the solver).
  if (result.report.reusedSavedSolution && view.chart) {
    view.chart = false;
    logInfo("no convergence chart: the reused solution has no iterations to replay");
  }
  if (view.chart) {
    while (!live.converged()) live.step();
    logInfo("replayed " + std::to_string(live.iterations()) +
            " iterations for the convergence chart");
  }
  show(data, toneMap, &live);
}

}  // namespace

void registerViewCommand(CLI::App& app, CommandAction& run) {
  auto options = std::make_shared<SolveOptions>();
  auto args = std::make_shared<ViewArgs>();
  CLI::App* view =
      app.add_subcommand("view", "Show a solution in a VTK window (or render it to a PNG)");
  view->add_option(
          "input", args->input,
          std::string(kSceneFileHelp) + ", solved first, or a directory holding solution.vtp")
      ->required();
  view->add_option("--screenshot", args->screenshot,
                   "Render off-screen to this PNG instead of opening a window");
  view->add_option("--size", args->size, "Window or image size WIDTHxHEIGHT")
      ->default_val(args->size);
  view->add_flag("--camera-from-scene", args->cameraFromScene,
                 "Use <scene>.camera.json next to the OBJ (position, look_at, up, vfov_degrees)");
  view->add_option("--scalar", args->scalar, "Colour the mesh by: " + displayScalarNames())
      ->default_val(args->scalar);
  view->add_flag("--smooth", args->smooth, "Interpolated vertex colours instead of flat elements");
  view->add_flag("--edges", args->edges, "Show element edges");
  view->add_flag("--outlines", args->outlines, "Show patch outlines");
  view->add_flag("--no-chart", args->noChart,
                 "No convergence panel (and no replay of the solve); the panel shows only in "
                 "windows at least 640x240");
  view->add_flag("--no-help", args->noHelp, "Start without the key overlay");
  view->add_option("--rays-of", args->raysOf,
                   "Draw the form-factor rays of this element (--solver hierarchical: its links)")
      ->check(nonNegativeNumber());
  view->add_option(
          "--stop-after", args->stopAfter,
          "Show the solver restarted from B = E after this many iterations (shots, sweeps)")
      ->check(nonNegativeNumber());
  view->add_option("--solution", args->solutionDir,
                   "Show the solution `radiosity solve` saved in this directory for the scene "
                   "(same solve options) instead of solving");
  auto* probes = view->add_option("--probes", args->probes,
                                  "Show the light probes of this probes.bin (solve --probes) as "
                                  "spheres; default: DIR/probes.bin of view DIR or --solution DIR");
  view->add_flag("--no-probes", args->noProbes, "Do not read or show light probes")
      ->excludes(probes);
  addSolveOptions(*view, *options);
  addCommonFlags(*view);
  view->callback([&run, view, options, args] {
    run = [view, options, args] { runView(*args, *options, *view); };
  });
}

}  // namespace rad
