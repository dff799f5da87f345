#pragma once

#include <string>
#include <vector>

#include "radiosity/scene/scene.h"

namespace rad {

// Which surfaces of an OBJ scene are two-sided (glTF says it per material with `doubleSided`):
// --two-sided (all of them) and --two-sided-materials A,B.
struct TwoSidedInput {
  bool all = false;
  std::vector<std::string> materials;
};

// Sets Material::twoSided as `input` says (on top of what the scene file said): `all` marks every
// material that does not emit, `materials` the named ones (emitters too: a two-sided emitter
// emits from both sides). Throws InputError naming the scene and the option when a listed
// material is not in the scene.
void applyTwoSidedInput(Scene& scene, const TwoSidedInput& input);

// A two-sided surface is meshed as two one-sided ones: each polygon whose material is two-sided
// gets a reversed copy (ScenePolygon::backSideOf) appended, with vertices of its own so that each
// side is refined on its own and the mesh stays manifold. Every later stage then gives each side
// its own radiosity; the ray caster lets a ray see only the side that faces it. Dielectrics get
// no copy (their back is their inside). Returns the number of copies added; calling it again
// adds none.
int addBackSides(Scene& scene);

}  // namespace rad
