#include "radiosity/render/bdpt.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "radiosity/render/scattering.h"

namespace rad {
namespace {

// Area density of reaching `to` by a direction from `from` drawn with solid-angle density
// `pdfDir`: pdfDir · |cos θ_to| / d².
double toArea(double pdfDir, const Eigen::Vector3d& from, const SurfaceHit& to) {
  const Eigen::Vector3d d = to.position - from;
  const double d2 = d.squaredNorm();
  return pdfDir * std::abs(to.normal.dot(d)) / (std::sqrt(d2) * d2);
}

// Densities along a specular chain x_a S…S x_b (x_a, x_b diffuse or on an emitter) are stored as
// 0 and count as 1 in the ratios: no strategy connects inside the chain, so a ratio crosses it
// whole, as p→(x_a)·p→(x_b | x_a) / (p←(x_a | x_b)·p←(x_b)). Both ends sample cosine-weighted
// directions (Lambertian bounce, Lambertian emission), so p→(x_b | x_a) = (cos_a/π)·G/cos_a and
// p←(x_a | x_b) = (cos_b/π)·G/cos_b are both G/π, with G the chain's generalised geometry term
// (symmetric: étendue is conserved through mirrors and glass). They cancel exactly, leaving
// p→(x_a)/p←(x_b); the chain's Fresnel choices have the same probability both ways.
double remap0(double pdf) { return pdf != 0 ? pdf : 1; }

}  // namespace

Bdpt::Bdpt(const RenderScene& scene, const Camera& camera, BdptOptions options)
    : scene_(scene), camera_(camera), rays_(camera), options_(options) {
  tanHalfY_ = std::tan(0.5 * camera.vfovDegrees * M_PI / 180.0);
  tanHalfX_ = tanHalfY_ * camera.width / camera.height;
  imagePlaneArea_ = 4 * tanHalfX_ * tanHalfY_;
}

double Bdpt::cameraPdf(const Eigen::Vector3d& direction) const {
  const double cosTheta = direction.dot(rays_.forward());
  if (!(cosTheta > 0)) return 0;
  return 1 / (imagePlaneArea_ * cosTheta * cosTheta * cosTheta);
}

std::string Bdpt::name() const {
  return std::string("bidirectional path tracing (") +
         (options_.heuristic == MisHeuristic::Power ? "power" : "balance") + " heuristic)";
}

void Bdpt::walk(std::vector<Vertex>& path, Eigen::Vector3d origin, Eigen::Vector3d direction,
                Rgb beta, double pdfDir, bool fromLight, Rng& rng, RayCounts& counts,
                Escape* escape) const {
  int diffuseBounces = 0, specularRun = 0;
  for (;;) {
    const SurfaceHit hit = scene_.intersect(origin, direction);
    ++(!fromLight && path.size() == 1 ? counts.camera : counts.closest);
    if (!hit.hit()) {
      if (escape) *escape = {true, direction, beta, path.size() == 1 || path.back().specular};
      return;
    }
    Vertex& prev = path.back();
    Vertex v;
    v.hit = hit;
    v.beta = beta;
    v.pdfFwd = prev.specular ? 0.0 : toArea(pdfDir, prev.hit.position, hit);
    const Material& m = *hit.material;

    if (m.isSpecular()) {
      v.pdfFwd = 0;  // see misWeight: a specular chain enters the weights as a whole
      // v.beta keeps the throughput arriving here; beta moves on past the mirror or glass.
      if (!continueSpecular(
              scene_, hit, origin, direction, beta, [&] { return rng.uniform(); },
              fromLight ? Transport::Importance : Transport::Radiance))
        return;
      v.specular = true;
      v.label = 'S';
      prev.pdfRev = 0;  // a delta seen from the specular vertex
      path.push_back(v);
      if (++specularRun > kSpecularRouletteAfter && !survivesRoulette(beta, rng.uniform())) return;
      continue;
    }
    specularRun = 0;
    if (!hit.front) return;  // back faces are black
    // A cosine bounce from here back to the previous vertex (Lambertian scattering or emission
    // both are cosine-distributed, whatever the incoming direction).
    const Eigen::Vector3d back = (prev.hit.position - hit.position).normalized();
    if (prev.specular)
      prev.pdfRev = 0;
    else if (path.size() > 1 || fromLight)
      prev.pdfRev = toArea(std::max(0.0, hit.normal.dot(back)) / M_PI, hit.position, prev.hit);
    v.label = 'D';
    path.push_back(v);

    const Rgb rho = hit.diffuse;
    if (rho.maxComponent() == 0) return;
    direction = cosineDirection(hit.normal, rng.uniform(), rng.uniform());
    pdfDir = hit.normal.dot(direction) / M_PI;
    if (!(pdfDir > 0)) return;
    origin = scene_.spawn(hit, direction);
    beta = beta * rho;  // f·cos/pdf = ρ
    if (++diffuseBounces >= options_.rouletteAfter && !survivesRoulette(beta, rng.uniform()))
      return;
  }
}

// Veach's weight of strategy (s, t) for the path y0…y_{s−1} z_{t−1}…z0: p_s^β / Σ p_i^β over the
// strategies used (t ≥ 2 or t ≥ 1, connecting edge without a specular end), computed by walking the
// ratios p_{i±1}/p_i = pdf of a vertex from the other side / from its own side. `lightEndRev` and
// `eyeEndRev` are the reverse densities of y_{s−1} and z_{t−1} for this connection.
double Bdpt::misWeight(const std::vector<Vertex>& light, const std::vector<Vertex>& eye, int s,
                       int t, double lightEndRev, double eyeEndRev, bool lightTracing) const {
  const bool power = options_.heuristic == MisHeuristic::Power;
  auto h = [power](double x) { return power ? x * x : x; };
  double sum = 0, ratio = 1;
  // Fewer eye vertices: z_i moves to the light side (t' = i ≥ 2, or ≥ 1 when light tracing).
  for (int i = t - 1; i >= (lightTracing ? 1 : 2); --i) {
    const double rev = i == t - 1 ? eyeEndRev : eye[i].pdfRev;
    ratio *= h(remap0(rev) / remap0(eye[i].pdfFwd));
    if (!eye[i].specular && !eye[i - 1].specular) sum += ratio;
  }
  // Fewer light vertices: y_i moves to the eye side (s' = i ≥ 0; s' = 0 hits the emitter).
  ratio = 1;
  for (int i = s - 1; i >= 0; --i) {
    const double rev = i == s - 1 ? lightEndRev : light[i].pdfRev;
    ratio *= h(remap0(rev) / remap0(light[i].pdfFwd));
    if (!light[i].specular && !(i > 0 && light[i - 1].specular)) sum += ratio;
  }
  return 1 / (1 + sum);
}

class Bdpt::Tally {
 public:
  Tally(const PathBinning* binning, Rgb* binned, const std::vector<Vertex>& eye,
        const std::vector<Vertex>& light)
      : binning_(binning), binned_(binned) {
    if (!binning_) return;
    eyeLabels_.clear();
    for (size_t i = 1; i < eye.size(); ++i) eyeLabels_.push_back(eye[i].label);
    lightLabels_.clear();
    for (size_t i = 1; i < light.size(); ++i) lightLabels_.push_back(light[i].label);
  }

  // Strategy (s, t)'s contribution `c` to this camera sample's pixel.
  void add(const Rgb& c, int s, int t) {
    sum_ += c;
    if (!binning_) return;
    // The light-side vertices y1…y_{s−1}, then z_{t−1}…z1 (for s = 0, z_{t−1} itself is L).
    const std::string_view lightSide = std::string_view(lightLabels_).substr(0, s > 0 ? s - 1 : 0);
    const std::string_view eyeSide = std::string_view(eyeLabels_).substr(0, s > 0 ? t - 1 : t - 2);
    lightToEyeLabel(label_, lightSide, eyeSide);
    const int bin = binning_->binOf(label_);
    if (bin >= 0) binned_[bin] += c;
  }

  // The bin of the light-traced path y0…y_{s−1}E (t = 1); −1 without binning.
  int lightTracingBin(int s) {
    if (!binning_) return -1;
    lightToEyeLabel(label_, std::string_view(lightLabels_).substr(0, s - 1), {});
    return binning_->binOf(label_);
  }

  const Rgb& sum() const { return sum_; }

 private:
  const PathBinning* binning_;
  Rgb* binned_;
  Rgb sum_;
  // Kept from sample to sample, so that labelling does not allocate once they have grown.
  static thread_local std::string eyeLabels_, lightLabels_, label_;
};

thread_local std::string Bdpt::Tally::eyeLabels_, Bdpt::Tally::lightLabels_, Bdpt::Tally::label_;

void Bdpt::traceEyePath(std::vector<Vertex>& eye, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& direction, Rng& rng, RayCounts& counts,
                        Escape& escape) const {
  // z0 is the camera (its densities never enter the weights: t ≥ 1 always).
  eye.clear();
  Vertex camera;
  camera.hit.position = origin;
  camera.hit.normal = direction;  // unused: the camera is never a connection end
  camera.label = 'E';
  eye.push_back(camera);
  walk(eye, origin, direction, Rgb::all(1.0), cameraPdf(direction), false, rng, counts, &escape);
}

void Bdpt::traceLightPath(std::vector<Vertex>& light, Rng& rng, RayCounts& counts) const {
  // y0 is a point on an emitter; the emission is cosine-distributed.
  light.clear();
  const EmitterSampler& lights = scene_.emitters();
  if (lights.empty()) return;
  const EmitterSample e = lights.sample(rng.uniform(), rng.uniform(), rng.uniform());
  Vertex y0;
  y0.hit.element = e.element;
  y0.hit.position = e.position;
  y0.hit.normal = e.normal;
  y0.hit.front = true;
  y0.hit.material = &scene_.material(e.element);
  y0.hit.diffuse = y0.hit.material->diffuse;  // never scattered: y0 only emits
  y0.beta = e.radiance / e.pdfArea;
  y0.pdfFwd = e.pdfArea;
  y0.label = 'L';
  light.push_back(y0);
  const Eigen::Vector3d d = cosineDirection(e.normal, rng.uniform(), rng.uniform());
  const double pdfDir = e.normal.dot(d) / M_PI;
  if (pdfDir > 0)  // Le·cos / (pdfArea · cos/π)
    walk(light, scene_.spawn(y0.hit, d), d, y0.beta * M_PI, pdfDir, true, rng, counts);
}

void Bdpt::connectEyeVertex(const std::vector<Vertex>& light, const std::vector<Vertex>& eye, int t,
                            bool lightTracing, Rng& rng, RayCounts& counts, Tally& tally) const {
  const Vertex& z = eye[t - 1];
  if (z.specular) return;
  const Material& mz = *z.hit.material;

  // s = 0: the eye sub-path reached an emitter's front.
  if (mz.isEmitter()) {
    const double w =
        misWeight(light, eye, 0, t, 0, scene_.emitters().pdfArea(z.hit.element), lightTracing);
    tally.add(z.beta * mz.emission * w, 0, t);
  }
  if (z.hit.diffuse.maxComponent() == 0) return;

  // The point, spot, directional and sky lights at z_{t−1}: labelled as a connection (s = 1).
  const SceneLights& sceneLights = scene_.lights();
  if (!sceneLights.empty()) {
    RandomSampler lightsSampler(rng);
    tally.add(z.beta * z.hit.diffuse *
                  (sceneLights.sampleIrradiance(scene_, z.hit, lightsSampler, counts, 1) / M_PI),
              1, t);
  }

  // s ≥ 1: connect y_{s−1} and z_{t−1} by a shadow ray.
  const int lightCount = static_cast<int>(light.size());
  for (int s = 1; s <= lightCount; ++s)
    if (const std::optional<Rgb> c = connect(light, eye, s, t, lightTracing, counts))
      tally.add(*c, s, t);
}

std::optional<Rgb> Bdpt::connect(const std::vector<Vertex>& light, const std::vector<Vertex>& eye,
                                 int s, int t, bool lightTracing, RayCounts& counts) const {
  const Vertex& y = light[s - 1];
  const Vertex& z = eye[t - 1];
  if (y.specular || y.hit.element == z.hit.element) return std::nullopt;
  const Rgb fy = s == 1 ? Rgb::all(1.0) : y.hit.diffuse / M_PI;  // Le is in y0.beta
  if (fy.maxComponent() == 0) return std::nullopt;
  Eigen::Vector3d w = y.hit.position - z.hit.position;
  const double d2 = w.squaredNorm();
  w /= std::sqrt(d2);
  const double cosZ = z.hit.normal.dot(w), cosY = -y.hit.normal.dot(w);
  if (cosZ <= 0 || cosY <= 0) return std::nullopt;  // one-sided surfaces and emitters
  ++counts.shadow;
  if (scene_.occluded(scene_.spawn(z.hit, w), y.hit.position)) return std::nullopt;
  // Either end reached from the other by a cosine-distributed direction: cos·cos/(π d²).
  const double pdfAcross = cosY * cosZ / (M_PI * d2);
  const double weight = misWeight(light, eye, s, t, pdfAcross, pdfAcross, lightTracing);
  return y.beta * fy * (z.hit.diffuse / M_PI) * z.beta * (cosY * cosZ / d2 * weight);
}

Rgb Bdpt::escapedRadiance(const Escape& escape, const Eigen::Vector3d& normal) const {
  const SceneLights& sceneLights = scene_.lights();
  return escape.beta * (escape.afterDelta
                            ? sceneLights.escapedRadiance(escape.direction)
                            : sceneLights.escapedRadiance(escape.direction, normal, 1));
}

// Per camera sample the value is beta·f·cos_y/(A cos³θ d²); the renderer divides by the samples
// per pixel.
void Bdpt::splatToCamera(const std::vector<Vertex>& light, const std::vector<Vertex>& eye,
                         RayCounts& counts, Tally& tally, SplatImage& splats) const {
  const double sx = tanHalfX_, sy = tanHalfY_;
  const int lightCount = static_cast<int>(light.size());
  for (int s = 1; s <= lightCount; ++s) {
    const Vertex& y = light[s - 1];
    if (y.specular) continue;
    const Rgb fy = s == 1 ? Rgb::all(1.0) : y.hit.diffuse / M_PI;
    if (fy.maxComponent() == 0) continue;
    Eigen::Vector3d w = camera_.position - y.hit.position;  // towards the camera
    const double d2 = w.squaredNorm();
    w /= std::sqrt(d2);
    const double cosY = y.hit.normal.dot(w);
    const double pdfDir = cameraPdf(-w);
    if (cosY <= 0 || pdfDir == 0) continue;
    const Eigen::Vector3d v = -w;
    const double f = v.dot(rays_.forward());
    const double px = (v.dot(rays_.right()) / f / sx + 1) * 0.5 * camera_.width;
    const double py = (1 - v.dot(rays_.up()) / f / sy) * 0.5 * camera_.height;
    if (!(px >= 0 && px < camera_.width && py >= 0 && py < camera_.height)) continue;
    ++counts.shadow;
    if (scene_.occluded(scene_.spawn(y.hit, w), camera_.position)) continue;
    const double pdfFromCamera = pdfDir * cosY / d2;  // area density of y from the camera
    const double weight = misWeight(light, eye, s, 1, pdfFromCamera, 0, true);
    const Rgb c = y.beta * fy * (pdfDir * cosY / d2 * weight);
    splats.add(std::min(static_cast<int>(px), camera_.width - 1),
               std::min(static_cast<int>(py), camera_.height - 1), c, tally.lightTracingBin(s));
  }
}

Rgb Bdpt::trace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
                RayCounts& counts, const PathBinning* binning, Rgb* binned,
                SplatImage* splats) const {
  // The sub-paths draw from the pixel's free stream: their dimensions vary in number, and the
  // connections, not stratification, are what lowers bdpt's variance.
  Rng& rng = sampler.rng();
  thread_local std::vector<Vertex> eye, light;
  const SceneLights& sceneLights = scene_.lights();
  if (scene_.emitters().empty() && sceneLights.empty()) return Rgb();

  // Light tracing needs a pinhole: a lens point would be one more sampled vertex.
  const bool lightTracing = splats != nullptr && camera_.lensRadius == 0;
  Escape escape;
  traceEyePath(eye, origin, direction, rng, counts, escape);
  traceLightPath(light, rng, counts);

  Tally tally(binning, binned, eye, light);
  const int eyeCount = static_cast<int>(eye.size());
  for (int t = 2; t <= eyeCount; ++t)
    connectEyeVertex(light, eye, t, lightTracing, rng, counts, tally);
  // The eye sub-path left the scene: the sky and the sun's disc, as if at one more eye vertex.
  if (escape.escaped && !sceneLights.empty())
    tally.add(escapedRadiance(escape, eye.back().hit.normal), 0, eyeCount + 1);
  // t = 1: connect each light vertex to the camera, splatted to the pixel it projects to.
  if (lightTracing) splatToCamera(light, eye, counts, tally, *splats);
  return tally.sum();
}

}  // namespace rad
