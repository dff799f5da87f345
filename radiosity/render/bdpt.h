#pragma once

#include <optional>
#include <string>
#include <vector>

#include "radiosity/core/named_values.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/path_integrator.h"

namespace rad {

enum class MisHeuristic { Balance, Power };  // Veach's β = 1 and β = 2
// `render --mis` names, the one list of them.
inline const NameTable<MisHeuristic>& misHeuristicTable() {
  static const NameTable<MisHeuristic> table = {{"power", MisHeuristic::Power},
                                                {"balance", MisHeuristic::Balance}};
  return table;
}

struct BdptOptions {
  MisHeuristic heuristic = MisHeuristic::Power;
  int rouletteAfter = 3;  // diffuse bounces of either sub-path before Russian roulette
};

// Bidirectional path tracing (Veach 1997, ch. 10) on the path tracer's scene and materials: per
// camera sample one eye sub-path z0 (the camera) z1 … and one light sub-path y0 (a point on an
// emitter, chosen as next-event estimation chooses it) y1 …, each a random walk with cosine
// bounces at diffuse vertices, mirror reflection and Fresnel-chosen reflection/refraction at glass,
// Russian roulette and no depth limit. Every pair (y_{s−1}, z_{t−1}) of diffuse vertices is
// connected by a shadow ray (s ≥ 1), and an eye vertex on an emitter's front counts as s = 0.
// With a pinhole camera and a splat image, every diffuse light vertex (and y0) is also connected
// to the camera (light tracing, t = 1) and splatted to the pixel it projects to: the only
// strategy that sees caustics LS+DE directly. Specular vertices cannot be connected (their BSDF
// is a delta); the multiple-importance weights count exactly the strategies used in the call:
// all (s, t) with t ≥ 2, plus t = 1 when light tracing, whose connecting edge has no specular
// end. Each contribution is one full path with a definite Heckbert label, so it can be binned.
// The point, spot, directional and sky lights (scene_lights.h) are a separate, additive estimator
// on the eye sub-path alone, as in the path tracer: next-event estimation at each diffuse eye
// vertex, and the sky and the sun's disc where the eye sub-path leaves the scene, MIS-weighted
// between the two; they start no light sub-paths (so light tracing does not see them either).
class Bdpt : public PathIntegrator {
 public:
  // `camera`: the camera the images are rendered from; light tracing needs it (pinhole only).
  Bdpt(const RenderScene& scene, const Camera& camera, BdptOptions options = {});
  Rgb trace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
            RayCounts& counts, const PathBinning* binning, Rgb* binned,
            SplatImage* splats) const override;
  std::string name() const override;

  struct Vertex {
    SurfaceHit hit;     // for the camera vertex only the position is set
    Rgb beta;           // sub-path throughput up to (not including) this vertex's scattering
    double pdfFwd = 0;  // area density of this vertex from its own sub-path (0: after a delta)
    double pdfRev = 0;  // area density of this vertex from the other direction (0: before a delta)
    bool specular = false;
    char label = 'D';  // L (emitter point y0), D, S or E (camera)
  };

 private:
  // Where an eye sub-path left the scene: the ray the sky and the sun's disc are seen along.
  struct Escape {
    bool escaped = false;
    Eigen::Vector3d direction;
    Rgb beta;                // throughput along that ray
    bool afterDelta = true;  // from the camera, a mirror or glass: no light sample took a share
  };
  // Extends `path` from its last vertex along `direction`; `pdfDir` is the solid-angle density
  // of that direction (unused after a specular vertex). `escape` (eye sub-paths): set when the
  // walk ends by leaving the scene.
  void walk(std::vector<Vertex>& path, Eigen::Vector3d origin, Eigen::Vector3d direction, Rgb beta,
            double pdfDir, bool fromLight, Rng& rng, RayCounts& counts,
            Escape* escape = nullptr) const;
  double misWeight(const std::vector<Vertex>& light, const std::vector<Vertex>& eye, int s, int t,
                   double lightEndRev, double eyeEndRev, bool lightTracing) const;
  // A camera sample's sum of contributions, each also binned by its full path's Heckbert label
  // (defined in bdpt.cpp).
  class Tally;
  // z0 (the camera) z1 …: the eye sub-path along the camera ray.
  void traceEyePath(std::vector<Vertex>& eye, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& direction, Rng& rng, RayCounts& counts,
                    Escape& escape) const;
  // y0 (a point on an emitter) y1 …: the light sub-path; empty without emissive polygons.
  void traceLightPath(std::vector<Vertex>& light, Rng& rng, RayCounts& counts) const;
  // Every strategy that ends at the eye vertex z_{t−1} (t ≥ 2): s = 0, the scene lights, s ≥ 1.
  void connectEyeVertex(const std::vector<Vertex>& light, const std::vector<Vertex>& eye, int t,
                        bool lightTracing, Rng& rng, RayCounts& counts, Tally& tally) const;
  // Strategy (s ≥ 1, t ≥ 2): y_{s−1} and z_{t−1} joined by a shadow ray; none where they cannot
  // be joined or the ray is blocked.
  std::optional<Rgb> connect(const std::vector<Vertex>& light, const std::vector<Vertex>& eye,
                             int s, int t, bool lightTracing, RayCounts& counts) const;
  // The sky and the sun's disc along the ray the eye sub-path left the scene by; `normal`: the
  // last eye vertex's.
  Rgb escapedRadiance(const Escape& escape, const Eigen::Vector3d& normal) const;
  // t = 1 (light tracing): every light vertex joined to the camera and splatted to its pixel.
  void splatToCamera(const std::vector<Vertex>& light, const std::vector<Vertex>& eye,
                     RayCounts& counts, Tally& tally, SplatImage& splats) const;
  // Solid-angle density, per camera sample over the whole image, of the camera ray along the
  // unit `direction` (1/(A cos³θ), A the image plane's area at distance 1); 0 outside the view.
  double cameraPdf(const Eigen::Vector3d& direction) const;

  const RenderScene& scene_;
  Camera camera_;
  CameraRays rays_;
  double tanHalfX_, tanHalfY_, imagePlaneArea_;
  BdptOptions options_;
};

}  // namespace rad
