#pragma once

// --gather N and --light-rays N: the final gather over a radiosity solution, per diffuse eye hit
// (render, compare) or per texel (bake). What the two counts mean together (the shadow rays per
// hit, the direct/indirect split, whether rays are cast at all) is FinalGatherOptions' to say.
#include <CLI/CLI.hpp>
#include <string>

#include "radiosity/render/final_gather_options.h"

namespace rad {

// Binds --gather and --light-rays to `rays` (its values are the defaults); `where` names what
// the rays leave from ("diffuse eye hit", "texel").
void addGatherOptions(CLI::App& command, FinalGatherOptions& rays, const std::string& where);
// --gather alone (compare, which gathers with as many shadow rays).
void addGatherRaysOption(CLI::App& command, FinalGatherOptions& rays, const std::string& where);

// InputError unless both counts are >= 0.
void checkGatherOptions(const FinalGatherOptions& rays);

// The command's method gathers nothing: --gather and --light-rays, when given, are errors
// "NAME is not used: WHY".
void refuseGatherOptions(const CLI::App& command, const std::string& why);

}  // namespace rad
