// Uniform against adaptive meshing on the Cornell box, in object space: the error of each
// solution's displayed radiance (linear interpolation of the vertex values, what vertex colours
// and lightmaps show) against a converged reference, at the reference's element centroids,
// weighted by area (emitters excluded: they are exact in every solution).
//
//   mesh_error [--reference-elements N] [--out DIR] [--quick] [--breakdown]
//
// Every solve uses analytic form factors (patches shoot, elements receive) and progressive
// shooting to 1e-5. The reference is a uniform mesh of about N elements whose values are point
// values at the element centroids (one receiver point, 64 shadow rays per patch). A second
// reference on the same elements with twice the shooting-patch area and half the shadow rays
// (another seed) estimates how far the reference itself is from the truth. Adaptive solves start
// from a coarse uniform mesh (386 elements, each a shooting patch) and refine with threshold 0.1
// and the default passes and minimum area up to each element budget (--max-elements). For each
// adaptive solve the uniform element count with the same error is read off the uniform curve
// (log-log interpolation; extrapolated along its last segment, and flagged, past its end).
// The displayed radiance is what `radiosity solve` writes as vertex colours (from the values at
// each element's 3 receiver points); a second error column shows the same solves displayed the
// older way, each vertex the area-weighted mean of its elements' values. --quick: a smaller
// reference (2000) and the runs up to 2000 uniform / 1600 adaptive, for iterating (~1 min).
// --breakdown: each run's squared error split by OBJ object (floor, blocks, ...) on stdout.
// Writes DIR/mesh_error.csv and DIR/mesh_error.svg, and DIR/mesh_error.png with
// bench/plot_mesh_error.py when /usr/bin/python3 has matplotlib.
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "meshing/element_locator.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/log.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace {

using namespace rad;

constexpr double kTolerance = 1e-5;
constexpr double kThreshold = 0.1;  // adaptive: the relative displayed error that makes a candidate
const int kRefinePasses = SolveOptions().refinePasses;

struct Config {
  std::string kind;
  int startElements;  // target count of the uniform (start) mesh
  int budget;         // adaptive: --max-elements
};

SolveResult solveUniform(const Scene& scene, int elements) {
  SolveOptions options;
  options.formFactors = FormFactorMethod::Analytic;
  options.targetElements = elements;
  options.tolerance = kTolerance;
  return solveScene(scene, options);
}

// Starts from a uniform mesh whose elements are also the shooting patches (substructuring: the
// patches stay, the elements are refined under them), so the adaptive solves shoot from as many
// patches as the finest uniform solves below (8 × fewer patches than elements there).
SolveResult solveAdaptive(const Scene& scene, int startElements, int budget) {
  SolveOptions options;
  options.formFactors = FormFactorMethod::Analytic;
  options.targetElements = startElements;
  options.maxArea = buildPatchMesh(scene).totalArea() / startElements;
  options.patchArea = options.maxArea;
  options.tolerance = kTolerance;
  options.refineThreshold = kThreshold;
  options.refinePasses = kRefinePasses;
  options.maxElements = budget;
  return solveScene(scene, options);
}

// A reference solve: point values at the element centroids (one receiver point), shooting patches
// of patchFactor × the element area.
SolveResult solveReference(const Scene& scene, int elements, double patchFactor, int shadowRays,
                           uint64_t seed) {
  SolveOptions options;
  options.formFactors = FormFactorMethod::Analytic;
  options.maxArea = buildPatchMesh(scene).totalArea() / elements;
  options.patchArea = patchFactor * options.maxArea;
  options.receiverPoints = 1;
  options.shadowRays = shadowRays;
  options.seed = seed;
  options.tolerance = 1e-6;
  return solveScene(scene, options);
}

Eigen::Vector3d radiance(const Rgb& b) { return Eigen::Vector3d(b.r, b.g, b.b) / M_PI; }

// The displayed radiance of a solution at a point p of input polygon `patch`: linear interpolation
// of its vertex values over the element containing p (the nearest element of that patch if p is
// on none, by rounding).
class DisplayedRadiance {
 public:
  // elementMeans: vertices take the area-weighted mean of their elements' values (the display
  // before receiver-point values); otherwise the vertex colours `radiosity solve` writes.
  explicit DisplayedRadiance(const SolveResult& r, bool elementMeans = false)
      : interpolation_(*r.solution.mesh), locator_(*r.solution.mesh) {
    const std::vector<std::array<Rgb, 3>> none;
    for (const Rgb& l : interpolateVertexRadiance(interpolation_, r.solution.radiosity,
                                                  elementMeans ? none : r.solution.pointRadiosity))
      vertexValues_.emplace_back(l.r, l.g, l.b);
  }

  Eigen::Vector3d at(int patch, const Eigen::Vector3d& p) const {
    Eigen::Vector3d w;
    const auto& t = interpolation_.triangle(locator_.locate(patch, p, w));
    return w[0] * vertexValues_[t[0]] + w[1] * vertexValues_[t[1]] + w[2] * vertexValues_[t[2]];
  }

 private:
  VertexInterpolation interpolation_;
  ElementLocator locator_;
  std::vector<Eigen::Vector3d> vertexValues_;
};

// Relative RMS over the reference's non-emitting elements, area-weighted, of value(e) − truth(e).
// With `byObject`, also each OBJ object's share of the squared relative error (they sum to its
// square).
template <class Value>
double relativeRms(const SolveResult& reference, Value value,
                   std::map<std::string, double>* byObject = nullptr) {
  const PatchMesh& ref = *reference.solution.mesh;
  double num = 0, den = 0;
  std::map<std::string, double> parts;
  for (int e = 0; e < ref.elementCount(); ++e) {
    if (reference.solution.problem.emission[e].maxComponent() > 0) continue;
    const Eigen::Vector3d truth = radiance(reference.solution.radiosity[e]);
    const double squared = ref.area(e) * (value(e) - truth).squaredNorm();
    num += squared;
    parts[reference.solution.scene.polygons[ref.patch(e)].object] += squared;
    den += ref.area(e) * truth.squaredNorm();
  }
  if (byObject)
    for (const auto& [object, part] : parts) (*byObject)[object] = part / den;
  return std::sqrt(num / den);
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

int main(int argc, char** argv) {
  int referenceElements = 0;
  std::string outDir = "bench/mesh_results";
  bool quick = false, breakdown = false;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 < argc && flag == "--reference-elements")
      referenceElements = std::atoi(argv[++i]);
    else if (i + 1 < argc && flag == "--out")
      outDir = argv[++i];
    else if (flag == "--quick")
      quick = true;
    else if (flag == "--breakdown")
      breakdown = true;
    else {
      std::fprintf(
          stderr,
          "usage: mesh_error [--reference-elements N] [--out DIR] [--quick] [--breakdown]\n");
      return 2;
    }
  }
  if (referenceElements == 0) referenceElements = quick ? 2000 : 4000;
  if (referenceElements < 500) {
    std::fprintf(stderr, "mesh_error: --reference-elements must be at least 500\n");
    return 2;
  }
  setLogLevel(LogLevel::Quiet);
  const Scene scene = loadScene(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj");
  auto t0 = std::chrono::steady_clock::now();
  const SolveResult reference = solveReference(scene, referenceElements, 8, 64, 1);
  std::fprintf(stderr, "reference: %d elements, %d shooting patches, %.1f s\n",
               reference.solution.mesh->elementCount(), reference.report.shooters, seconds(t0));
  // How far is the reference from the truth? A second one on the same elements with coarser
  // shooting patches and fewer shadow rays (another seed) differs from it by about its own error
  // or more: the errors of both shrink with patch size and ray count.
  t0 = std::chrono::steady_clock::now();
  const SolveResult check = solveReference(scene, referenceElements, 16, 32, 2);
  const ElementLocator checkElements(*check.solution.mesh);
  const double referenceError = relativeRms(reference, [&](int e) {
    Eigen::Vector3d w;
    return radiance(check.solution.radiosity[checkElements.locate(
        reference.solution.mesh->patch(e), reference.solution.mesh->centroid(e), w)]);
  });
  std::fprintf(
      stderr,
      "reference check: %d elements, %d shooting patches, %.1f s: relative RMS difference %.4f\n",
      check.solution.mesh->elementCount(), check.report.shooters, seconds(t0), referenceError);

  std::vector<Config> configs;
  for (int n : {125, 250, 500, 1000, 2000, 4000})
    if (!quick || n <= 2000) configs.push_back({"uniform", n, 0});
  for (int budget : {800, 1600, 3200})
    if (!quick || budget <= 1600) configs.push_back({"adaptive", 250, budget});

  struct Point {
    Config config;
    int elements, shooters;
    double error, seconds, errorElementMeans;
  };
  std::vector<Point> points;
  for (const Config& c : configs) {
    t0 = std::chrono::steady_clock::now();
    const SolveResult r = c.kind == "uniform" ? solveUniform(scene, c.startElements)
                                              : solveAdaptive(scene, c.startElements, c.budget);
    const double time = seconds(t0);
    const DisplayedRadiance field(r), meansField(r, true);
    const PatchMesh& ref = *reference.solution.mesh;
    std::map<std::string, double> byObject;
    const double error = relativeRms(
        reference, [&](int e) { return field.at(ref.patch(e), ref.centroid(e)); }, &byObject);
    const double errorMeans =
        relativeRms(reference, [&](int e) { return meansField.at(ref.patch(e), ref.centroid(e)); });
    points.push_back(
        {c, r.solution.mesh->elementCount(), r.report.shooters, error, time, errorMeans});
    std::fprintf(stderr,
                 "%-8s start %5d budget %5d: %5d elements, %4d patches, relative RMS error %.4f "
                 "(element means: "
                 "%.4f) (%.1f s)\n",
                 c.kind.c_str(), c.startElements, c.budget, r.solution.mesh->elementCount(),
                 r.report.shooters, error, errorMeans, time);
    if (breakdown) {
      std::printf("%s %d elements: squared relative error %.5f =", c.kind.c_str(),
                  r.solution.mesh->elementCount(), error * error);
      for (const auto& [object, part] : byObject) std::printf(" %s %.5f", object.c_str(), part);
      std::printf("\n");
    }
  }

  // Uniform elements needed for the same error as each adaptive mesh: log-log interpolation along
  // the uniform curve, extrapolated along its last segment below its smallest error.
  std::vector<std::pair<double, double>>
      uniform;  // (log elements, log error), fewest elements first
  for (const Point& p : points)
    if (p.config.kind == "uniform") uniform.push_back({std::log(p.elements), std::log(p.error)});
  auto uniformElementsFor = [&](double error, bool& extrapolated) {
    const double y = std::log(error);
    size_t k = 1;
    while (k + 1 < uniform.size() && uniform[k].second > y) ++k;
    extrapolated = y < uniform.back().second || y > uniform.front().second;
    const auto& [x0, y0] = uniform[k - 1];
    const auto& [x1, y1] = uniform[k];
    return std::exp(x0 + (y - y0) * (x1 - x0) / (y1 - y0));
  };

  std::ofstream csv(outDir + "/mesh_error.csv");
  csv << "kind,start_target,budget,elements,shooting_patches,relative_rms_error,seconds,"
         "uniform_elements_same_error,element_ratio,extrapolated,relative_rms_error_element_"
         "means\n";
  for (const Point& p : points) {
    csv << p.config.kind << "," << p.config.startElements << "," << p.config.budget << ","
        << p.elements << "," << p.shooters << "," << p.error << "," << p.seconds << ",";
    if (p.config.kind == "adaptive") {
      bool extrapolated = false;
      const double same = uniformElementsFor(p.error, extrapolated);
      csv << std::lround(same) << "," << same / p.elements << "," << (extrapolated ? 1 : 0) << ","
          << p.errorElementMeans << "\n";
      std::printf(
          "adaptive %5d elements: error %.4f, uniform needs %5ld elements for it (%.2f×%s)\n",
          p.elements, p.error, std::lround(same), same / p.elements,
          extrapolated ? ", extrapolated" : "");
    } else {
      csv << ",,," << p.errorElementMeans << "\n";
      std::printf("uniform  %5d elements: error %.4f\n", p.elements, p.error);
    }
  }
  csv << "reference," << referenceElements << ",0," << reference.solution.mesh->elementCount()
      << "," << reference.report.shooters << "," << referenceError << ",0,,,,\n";
  std::printf("reference %d elements; its check differs from it by %.4f (relative RMS)\n",
              reference.solution.mesh->elementCount(), referenceError);
  csv.close();

  // Log-log plot, elements against error.
  double x0 = 1e9, x1 = 0, y0 = 1e9, y1 = 0;
  for (const auto& p : points) {
    x0 = std::min(x0, std::log10(p.elements));
    x1 = std::max(x1, std::log10(p.elements));
    y0 = std::min(y0, std::log10(p.error));
    y1 = std::max(y1, std::log10(p.error));
  }
  x0 -= 0.1;
  x1 += 0.1;
  y0 -= 0.1;
  y1 += 0.1;
  const double w = 640, h = 420, m = 60;
  auto px = [&](double x) { return m + (std::log10(x) - x0) / (x1 - x0) * (w - 2 * m); };
  auto py = [&](double y) { return h - m - (std::log10(y) - y0) / (y1 - y0) * (h - 2 * m); };
  std::ofstream svg(outDir + "/mesh_error.svg");
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"640\" height=\"420\" "
         "font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"640\" height=\"420\" fill=\"white\"/>\n"
      << "<line x1=\"60\" y1=\"360\" x2=\"580\" y2=\"360\" stroke=\"black\"/><line x1=\"60\" "
         "y1=\"60\" x2=\"60\" y2=\"360\" stroke=\"black\"/>\n"
      << "<text x=\"320\" y=\"405\" text-anchor=\"middle\">elements (log)</text>\n"
      << "<text x=\"15\" y=\"210\" transform=\"rotate(-90 15 210)\" "
         "text-anchor=\"middle\">relative RMS radiance error (log)</text>\n"
      << "<text x=\"320\" y=\"25\" text-anchor=\"middle\">Cornell box: uniform vs adaptive meshing "
         "(reference "
      << reference.solution.mesh->elementCount() << " elements)</text>\n";
  for (double v : {50., 100., 200., 500., 1000., 2000., 5000.})
    if (std::log10(v) > x0 && std::log10(v) < x1)
      svg << "<text x=\"" << px(v) << "\" y=\"378\" text-anchor=\"middle\">" << v << "</text>\n";
  for (double v : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2})
    if (std::log10(v) > y0 && std::log10(v) < y1)
      svg << "<text x=\"52\" y=\"" << py(v) + 4 << "\" text-anchor=\"end\">" << v << "</text>\n";
  for (const std::string kind : {"uniform", "adaptive"}) {
    const char* colour = kind == "uniform" ? "#2c3e50" : "#c0392b";
    svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
    for (const auto& p : points)
      if (p.config.kind == kind) svg << px(p.elements) << "," << py(p.error) << " ";
    svg << "\"/>\n";
    for (const auto& p : points)
      if (p.config.kind == kind)
        svg << "<circle cx=\"" << px(p.elements) << "\" cy=\"" << py(p.error)
            << "\" r=\"3\" fill=\"" << colour << "\"/>\n";
  }
  svg << "<text x=\"440\" y=\"70\" fill=\"#2c3e50\">uniform</text><text x=\"440\" y=\"86\" "
         "fill=\"#c0392b\">adaptive (threshold "
      << kThreshold << ")</text>\n</svg>\n";
  svg.close();

  // The PNG plot, where Debian's python has matplotlib (scripts/setup.sh --bench).
  const std::string plot =
      std::string("/usr/bin/python3 ") + RADIOSITY_SOURCE_DIR "/bench/plot_mesh_error.py " + outDir;
  if (std::system(plot.c_str()) != 0)
    std::fprintf(stderr, "mesh_error: no PNG plot (run %s by hand; it needs python3-matplotlib)\n",
                 plot.c_str());
  return 0;
}
