#include "radiosity/app/options/gather_options.h"

#include "radiosity/app/options/option_rules.h"
#include "radiosity/core/errors.h"

namespace rad {

void addGatherRaysOption(CLI::App& command, FinalGatherOptions& rays, const std::string& where) {
  command
      .add_option("--gather", rays.gatherRays,
                  "Final-gather rays into the solution (and as many shadow rays to the emitters) "
                  "per " +
                      where +
                      "; 0: the solution interpolated, or with --light-rays N the direct light "
                      "by N shadow rays and the solution's indirect light")
      ->default_val(rays.gatherRays);
}

void addGatherOptions(CLI::App& command, FinalGatherOptions& rays, const std::string& where) {
  addGatherRaysOption(command, rays, where);
  command
      .add_option("--light-rays", rays.lightRays,
                  "Shadow rays to the emitters per " + where +
                      " of the final gather, MIS-weighted against the --gather rays by their "
                      "counts; 0: as many as --gather; with --gather 0: the direct light by these "
                      "rays alone, the indirect light interpolated from the solution")
      ->default_val(rays.lightRays);
}

void checkGatherOptions(const FinalGatherOptions& rays) {
  if (rays.gatherRays < 0) throw InputError("--gather must be >= 0");
  if (rays.lightRays < 0) throw InputError("--light-rays must be >= 0");
}

void refuseGatherOptions(const CLI::App& command, const std::string& why) {
  for (const char* name : {"--gather", "--light-rays"}) refuseIfGiven(command, name, why);
}

}  // namespace rad
