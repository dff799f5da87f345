#pragma once

#include <string>

#include "radiosity/core/rgb.h"

namespace rad {

// How a surface scatters light. The radiosity pass treats every surface as Lambertian with
// reflectance `diffuse`; the specular fields are kept for the passes that follow mirrors/glass.
enum class SurfaceKind {
  Diffuse,     // illum 0, 1, 2 (and anything else that is not specular)
  Mirror,      // illum 3 or 5: perfect reflection with reflectance Ks
  Dielectric,  // illum 7: Fresnel reflection/refraction with index Ni and transmittance Tf
};

struct Material {
  std::string name;
  Rgb diffuse;             // Kd: Lambertian reflectance rho, each channel in [0, 1]
  Rgb emission;            // Ke: emitted radiance L_e in W m^-2 sr^-1 (front face only)
  Rgb specular;            // Ks: mirror reflectance
  Rgb transmittance;       // Tf: dielectric transmittance filter
  double ior = 1.0;        // Ni
  double shininess = 0.0;  // Ns
  int illum = 2;
  SurfaceKind kind = SurfaceKind::Diffuse;

  // Textures: indices into Scene::textures, -1 for none. A texture multiplies its factor
  // (map_Kd × Kd, baseColorTexture × baseColorFactor; map_Ke × Ke, emissiveTexture × emissive).
  int diffuseTexture = -1;
  int emissionTexture = -1;
  // Cut-outs: where the coverage (map_d, or the alpha of the diffuse texture when
  // `alphaFromDiffuse`) is below alphaCutoff, rays pass through the surface as if it were absent.
  int alphaTexture = -1;
  bool alphaFromDiffuse = false;
  double alphaCutoff = 0.5;
  // Seen, lit and reflecting on both sides (each side its own radiosity); otherwise the back of
  // the surface is black and receives nothing.
  bool twoSided = false;

  // Where the material was defined, for error messages about its values.
  std::string sourceFile;
  int sourceLine = 0;

  bool isEmitter() const { return emission.maxComponent() > 0; }
  bool hasCutouts() const { return alphaTexture >= 0 || alphaFromDiffuse; }
  bool isSpecular() const { return kind != SurfaceKind::Diffuse; }
};

}  // namespace rad
