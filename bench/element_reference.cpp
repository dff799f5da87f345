// A reference for per-element radiosity that no radiosity solver took part in: for a random
// sample of a mesh's elements, B = E + ρ · (the irradiance averaged over the element), the
// irradiance estimated by the project's path tracer (unbiased: next-event estimation, MIS,
// Russian roulette, no depth limit) from points spread uniformly over the element and
// cosine-weighted directions. The lights besides emissive polygons (sun, sky, lamps) are also
// sampled at the element's own points, as the path tracer does at every diffuse vertex: a sun's
// half-degree disc would otherwise reach a sunlit element only when a cosine ray happens to
// leave through it, and its noise would swamp the error sought. Solvers' elements.csv are compared
// with it on those elements (bench/hierarchical_scale.py); each value's standard error is written
// beside it, so the comparison can remove the reference's own noise.
//
//   element_reference SCENE --elements N --out FILE.csv [--sample K] [--paths M] [--seed S]
//                     [--threads T] [--lights FILE] [--sky ...]
//
// The mesh is the one `radiosity solve SCENE --elements N` makes (meshScene is deterministic);
// each sampled element's centroid is written, so a comparison can check it reads the same
// elements. Sampled: elements that emit nothing, are not mirrors or glass, and have no buried
// part (ElementExposure: a solve spreads a partly buried element's light over its exposed part
// only, which a uniform point sample would not), uniformly by index. ρ is the element's own
// (Kd times its texture's area average), so on a textured element the covariance of texture
// and irradiance within it is left out.
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/rng.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/render/path_tracer.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sampler.h"
#include "radiosity/render/scene_lights.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

struct Args {
  std::string scene, out, lights;
  int elements = 0, sample = 2000, paths = 16384, threads = 0;
  uint64_t seed = 7;
};

struct Estimate {
  Rgb mean, standardError;
};

// One next-event estimate of the irradiance at `point` from the scene's lights besides the
// emissive polygons: the delta lights exactly, each area light at infinity (sun disc, sky) by one
// shadow ray, MIS-weighted against one cosine ray (SceneLights::sampleIrradiance).
Rgb lightsAtInfinityAndLamps(const RenderScene& view, int e, const Eigen::Vector3d& point,
                             const Eigen::Vector3d& normal, Rng& rng, RayCounts& counts) {
  if (view.lights().empty()) return {};
  SurfaceHit at;
  at.element = e;
  at.position = point;
  at.normal = normal;
  at.front = true;
  RandomSampler sampler(rng);
  return view.lights().sampleIrradiance(view, at, sampler, counts, 1);
}

// The mean of M path-traced irradiance samples over the element, and its standard error.
Estimate elementIrradiance(const RenderScene& view, const PathTracer& tracer, int e, int paths,
                           uint64_t seed) {
  const PatchMesh& mesh = view.mesh();
  const auto corners = mesh.corners(e);
  const Eigen::Vector3d normal = mesh.normal(e);
  const Frame frame(normal);
  Rng rng(seed, static_cast<uint64_t>(e));
  // Stratified over the element and the hemisphere together: a √M × √M grid of (point, direction)
  // pairs, the point and the direction from independent jitters.
  const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(paths))));
  Rgb sum, sumSquares;
  RayCounts counts;
  int n = 0;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j, ++n) {
      const Eigen::Vector3d point =
          uniformPointOnTriangle(corners, (i + rng.uniform()) / side, rng.uniform());
      const Eigen::Vector3d direction =
          frame.toWorld(cosineWeightedDirection((j + rng.uniform()) / side, rng.uniform()));
      const Eigen::Vector3d origin = view.caster().liftOff(point, normal, direction);
      Rgb irradiance = lightsAtInfinityAndLamps(view, e, point, normal, rng, counts);
      if (view.intersect(origin, direction).hit())
        irradiance += M_PI * tracer.radiance(origin, direction, rng, counts);
      else  // out of the scene: the sky and sun by this ray's MIS weight against their samples
        irradiance += M_PI * view.lights().escapedRadiance(direction, normal, 1);
      sum += irradiance;
      sumSquares += irradiance * irradiance;
    }
  Estimate out;
  out.mean = sum / n;
  const Rgb variance = (sumSquares / n - out.mean * out.mean) / std::max(1, n - 1);
  out.standardError = {std::sqrt(std::max(0.0, variance.r)), std::sqrt(std::max(0.0, variance.g)),
                       std::sqrt(std::max(0.0, variance.b))};
  return out;
}

int run(const Args& args) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              args.threads > 0 ? args.threads : tbb::info::default_concurrency());
  SolveOptions options;
  options.scenePath = args.scene;
  options.targetElements = args.elements;
  if (!args.lights.empty()) options.lights.file = args.lights;
  const Scene scene =
      loadScene(args.scene, options.lights, options.twoSided, options.unreadableTextures);
  const MeshedScene meshed = meshScene(scene, options);
  const PatchMesh& mesh = *meshed.mesh;
  const RayCaster caster(mesh);
  const ElementExposure exposure(mesh, caster);
  const RadiosityProblem problem = makeProblem(scene, mesh);
  const std::vector<SpecularSurface> specular = specularSurfaces(scene, mesh);

  std::vector<int> candidates;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const bool emits = problem.emission[e].maxComponent() > 0;
    const bool mirrorOrGlass =
        !specular.empty() && specular[e].kind != SpecularSurface::Kind::Diffuse;
    if (!emits && !mirrorOrGlass && exposure.buriedCells(e) == 0) candidates.push_back(e);
  }
  if (candidates.empty()) throw InputError(args.scene + ": no element to sample");
  // K distinct elements, uniformly by index (a partial Fisher–Yates shuffle), in index order.
  Rng pick(args.seed, 0xE1E);
  const int k = std::min<int>(args.sample, static_cast<int>(candidates.size()));
  for (int i = 0; i < k; ++i)
    std::swap(candidates[i], candidates[i + pick.below(candidates.size() - i)]);
  std::vector<int> sampled(candidates.begin(), candidates.begin() + k);
  std::sort(sampled.begin(), sampled.end());

  const RenderScene view(scene, mesh, caster);
  const PathTracer tracer(view);
  std::vector<Estimate> estimates(sampled.size());
  Progress progress("element_reference", sampled.size(), "elements");
  tbb::parallel_for(0, static_cast<int>(sampled.size()), [&](int i) {
    estimates[i] = elementIrradiance(view, tracer, sampled[i], args.paths, args.seed);
    progress.advance();
  });
  progress.finish("of " + std::to_string(mesh.elementCount()) + ", " + std::to_string(args.paths) +
                  " paths each");

  AtomicFile file(args.out);
  std::ostream& f = file.stream();
  f << std::setprecision(17);
  f << "element,cx,cy,cz,B_r,B_g,B_b,se_r,se_g,se_b\n";
  for (size_t i = 0; i < sampled.size(); ++i) {
    const int e = sampled[i];
    const Eigen::Vector3d c = mesh.centroid(e);
    const Rgb rho = problem.reflectance[e];
    const Rgb b = problem.emission[e] + rho * estimates[i].mean;
    const Rgb se = rho * estimates[i].standardError;
    f << e << ',' << c.x() << ',' << c.y() << ',' << c.z() << ',' << b.r << ',' << b.g << ',' << b.b
      << ',' << se.r << ',' << se.g << ',' << se.b << '\n';
  }
  file.finish();
  file.commit();
  return 0;
}

}  // namespace
}  // namespace rad

int main(int argc, char** argv) {
  rad::Args args;
  CLI::App app("Per-element radiosity of a random sample of elements, path traced");
  app.add_option("scene", args.scene, "OBJ or glTF scene")->required();
  app.add_option("--elements", args.elements, "as radiosity solve --elements")->required();
  app.add_option("--out", args.out, "CSV to write")->required();
  app.add_option("--sample", args.sample, "elements to estimate")->default_val(args.sample);
  app.add_option("--paths", args.paths, "paths per element")->default_val(args.paths);
  app.add_option("--seed", args.seed)->default_val(args.seed);
  app.add_option("--threads", args.threads, "0: all")->default_val(args.threads);
  app.add_option("--lights", args.lights, "lights file, as radiosity solve --lights");
  CLI11_PARSE(app, argc, argv);
  try {
    return rad::run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "element_reference: %s\n", e.what());
    return 1;
  }
}
