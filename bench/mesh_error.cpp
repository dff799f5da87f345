// Uniform against adaptive meshing on the Cornell box, in object space: the error of each
// solution's interpolated radiance (what vertex colours and lightmaps show) against a fine
// reference solution, at the reference's element centroids, weighted by area.
//
//   mesh_error [--reference-elements N] [--out DIR]
//
// All solves use analytic form factors (patches shoot, elements receive) and progressive shooting
// to 1e-5. Writes DIR/mesh_error.csv and DIR/mesh_error.svg (elements against error, log-log).
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "meshing/vertex_interpolation.h"
#include "radiosity/app/solve_job.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/obj_loader.h"

namespace {

using namespace rad;

struct Config {
  std::string kind;
  int elements;
  double threshold;
};

SolveResult solve(const Scene& scene, int elements, double threshold) {
  SolveOptions options;
  options.formFactors = FormFactorMethod::Analytic;
  options.targetElements = elements;
  options.tolerance = 1e-5;
  options.refineThreshold = threshold;
  options.refinePasses = 3;
  return solveScene(scene, options);
}

// Radiance of `result` at point p on input polygon `patch`, interpolated from its vertex values
// over the element containing p (nearest element of that patch if p is on no element).
class RadianceField {
 public:
  explicit RadianceField(const SolveResult& r) : result_(r), interpolation_(*r.mesh) {
    std::vector<Eigen::Vector3d> perElement(r.radiosity.size());
    for (size_t e = 0; e < perElement.size(); ++e)
      perElement[e] = Eigen::Vector3d(r.radiosity[e].r, r.radiosity[e].g, r.radiosity[e].b) / M_PI;
    vertexValues_ = interpolation_.interpolate(perElement);
    byPatch_.resize(r.mesh->patchCount());
    for (int e = 0; e < r.mesh->elementCount(); ++e) byPatch_[r.mesh->patch(e)].push_back(e);
  }

  Eigen::Vector3d at(int patch, const Eigen::Vector3d& p) const {
    const PatchMesh& mesh = *result_.mesh;
    int best = -1;
    double bestOutside = 1e300;
    Eigen::Vector3d bestWeights = Eigen::Vector3d::Zero();
    for (int e : byPatch_[patch]) {
      const auto c = mesh.corners(e);
      const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
      const double area2 = n.squaredNorm();
      Eigen::Vector3d w;
      for (int k = 0; k < 3; ++k) w[k] = (c[(k + 1) % 3] - p).cross(c[(k + 2) % 3] - p).dot(n) / area2;
      const double outside = -std::min(0.0, w.minCoeff());
      if (outside < bestOutside) {
        bestOutside = outside;
        best = e;
        bestWeights = w;
        if (outside == 0) break;
      }
    }
    const auto& t = interpolation_.triangle(best);
    return bestWeights[0] * vertexValues_[t[0]] + bestWeights[1] * vertexValues_[t[1]] +
           bestWeights[2] * vertexValues_[t[2]];
  }

 private:
  const SolveResult& result_;
  VertexInterpolation interpolation_;
  std::vector<Eigen::Vector3d> vertexValues_;
  std::vector<std::vector<int>> byPatch_;
};

}  // namespace

int main(int argc, char** argv) {
  int referenceElements = 6000;
  std::string outDir = "bench/mesh_results";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--reference-elements") referenceElements = std::stoi(argv[i + 1]);
    else if (flag == "--out") outDir = argv[i + 1];
    else {
      std::fprintf(stderr, "usage: mesh_error [--reference-elements N] [--out DIR]\n");
      return 2;
    }
  }
  setLogLevel(LogLevel::Quiet);
  const Scene scene = loadObjScene(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj");
  auto t0 = std::chrono::steady_clock::now();
  const SolveResult reference = solve(scene, referenceElements, 0);
  std::fprintf(stderr, "reference: %d elements in %.1f s\n", reference.mesh->elementCount(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());

  std::vector<Config> configs;
  for (int n : {125, 250, 500, 1000, 2000}) configs.push_back({"uniform", n, 0});
  for (int n : {125, 250, 500}) configs.push_back({"adaptive", n, 0.1});
  for (int n : {125, 250}) configs.push_back({"adaptive", n, 0.05});

  std::ofstream csv(outDir + "/mesh_error.csv");
  csv << "kind,target_elements,elements,relative_rms_error,seconds\n";
  struct Point { std::string kind; int elements; double error; };
  std::vector<Point> points;
  for (const Config& c : configs) {
    t0 = std::chrono::steady_clock::now();
    const SolveResult r = solve(scene, c.elements, c.threshold);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const RadianceField field(r);
    double num = 0, den = 0;
    const PatchMesh& ref = *reference.mesh;
    for (int e = 0; e < ref.elementCount(); ++e) {
      if (reference.problem.emission[e].maxComponent() > 0) continue;  // emitters are exact in both
      const Eigen::Vector3d truth =
          Eigen::Vector3d(reference.radiosity[e].r, reference.radiosity[e].g, reference.radiosity[e].b) / M_PI;
      const Eigen::Vector3d value = field.at(ref.patch(e), ref.centroid(e));
      num += ref.area(e) * (value - truth).squaredNorm();
      den += ref.area(e) * truth.squaredNorm();
    }
    const double error = std::sqrt(num / den);
    points.push_back({c.kind, r.mesh->elementCount(), error});
    csv << c.kind << "," << c.elements << "," << r.mesh->elementCount() << "," << error << "," << seconds << "\n";
    std::printf("%-9s target %5d  elements %5d  relative RMS error %.4f  (%.1f s)\n", c.kind.c_str(), c.elements,
                r.mesh->elementCount(), error, seconds);
    std::fflush(stdout);
  }

  // Log-log plot, elements against error.
  double x0 = 1e9, x1 = 0, y0 = 1e9, y1 = 0;
  for (const auto& p : points) {
    x0 = std::min(x0, std::log10(p.elements)); x1 = std::max(x1, std::log10(p.elements));
    y0 = std::min(y0, std::log10(p.error)); y1 = std::max(y1, std::log10(p.error));
  }
  x0 -= 0.1; x1 += 0.1; y0 -= 0.1; y1 += 0.1;
  const double w = 640, h = 420, m = 60;
  auto px = [&](double x) { return m + (std::log10(x) - x0) / (x1 - x0) * (w - 2 * m); };
  auto py = [&](double y) { return h - m - (std::log10(y) - y0) / (y1 - y0) * (h - 2 * m); };
  std::ofstream svg(outDir + "/mesh_error.svg");
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"640\" height=\"420\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"640\" height=\"420\" fill=\"white\"/>\n"
      << "<line x1=\"60\" y1=\"360\" x2=\"580\" y2=\"360\" stroke=\"black\"/><line x1=\"60\" y1=\"60\" x2=\"60\" y2=\"360\" stroke=\"black\"/>\n"
      << "<text x=\"320\" y=\"405\" text-anchor=\"middle\">elements (log)</text>\n"
      << "<text x=\"15\" y=\"210\" transform=\"rotate(-90 15 210)\" text-anchor=\"middle\">relative RMS radiance error (log)</text>\n"
      << "<text x=\"320\" y=\"25\" text-anchor=\"middle\">Cornell box: uniform vs adaptive meshing (reference " << reference.mesh->elementCount() << " elements)</text>\n";
  for (double v : {50., 100., 200., 500., 1000., 2000., 5000.})
    if (std::log10(v) > x0 && std::log10(v) < x1) svg << "<text x=\"" << px(v) << "\" y=\"378\" text-anchor=\"middle\">" << v << "</text>\n";
  for (double v : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2})
    if (std::log10(v) > y0 && std::log10(v) < y1) svg << "<text x=\"52\" y=\"" << py(v) + 4 << "\" text-anchor=\"end\">" << v << "</text>\n";
  for (const std::string kind : {"uniform", "adaptive"}) {
    const char* colour = kind == "uniform" ? "#2c3e50" : "#c0392b";
    svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
    for (const auto& p : points) if (p.kind == kind) svg << px(p.elements) << "," << py(p.error) << " ";
    svg << "\"/>\n";
    for (const auto& p : points)
      if (p.kind == kind) svg << "<circle cx=\"" << px(p.elements) << "\" cy=\"" << py(p.error) << "\" r=\"3\" fill=\"" << colour << "\"/>\n";
  }
  svg << "<text x=\"460\" y=\"70\" fill=\"#2c3e50\">uniform</text><text x=\"460\" y=\"86\" fill=\"#c0392b\">adaptive (threshold 0.3)</text>\n</svg>\n";
  return 0;
}
