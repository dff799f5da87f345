#pragma once

#include <Eigen/Core>

#include "radiosity/core/rgb.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sampler.h"

namespace rad {

// Where an eye ray meets the first diffuse surface's front, through mirrors and glass (past
// kSpecularRouletteAfter bounces by Russian roulette, with no cut-off), the chain's random numbers
// drawn from the sampler: what the eye passes over a radiosity solution share before each reads
// the diffuse surface its own way.
struct DiffuseEyeHit {
  bool reached = false;  // a diffuse surface's front; otherwise `radiance` is the ray's
  SurfaceHit hit;
  Rgb weight;    // the mirrors' and glass's factor along the way
  Rgb radiance;  // not reached: the sky it left into (times the weight), or nothing (absorbed)
};

// The first ray from `origin` counts as a camera ray, the chain's as closest-hit rays.
DiffuseEyeHit traceToDiffuse(const RenderScene& scene, Eigen::Vector3d origin,
                             Eigen::Vector3d direction, Sampler& sampler, RayCounts& counts);

}  // namespace rad
