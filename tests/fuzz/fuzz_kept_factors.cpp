// libFuzzer target: factors.bin, what `solve --keep-factors` keeps for `relight`, through its one
// reader, readKeptFactors() (radiosity/pipeline/kept_factors.h). Every error must name the file;
// a file it accepts must hold what relight indexes without checking (one row per element,
// targets in range and increasing, E_d per light and element) with finite, non-negative values,
// and written back with writeKeptFactors it must read again the same. Findings: crashes,
// sanitizer reports, and any exception other than InputError.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/kept_factors.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_kept_factors: %s\n", what);
  std::abort();
}

bool finiteNonNegative(double x) { return std::isfinite(x) && x >= 0; }
bool valid(const rad::Rgb& c) { return c.isFinite() && c.minComponent() >= 0; }

// readKeptFactors, where any exception but an InputError naming the file is a finding.
std::optional<rad::KeptFactors> read(const std::string& path) {
  try {
    return rad::readKeptFactors(path);
  } catch (const rad::InputError& e) {
    check(e.file() == path, "an error does not name the file");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_kept_factors: not an InputError: %s\n", e.what());
    std::abort();
  }
  return std::nullopt;
}

void checkKept(const rad::KeptFactors& k) {
  const size_t n = k.area.size();
  check(k.rows.size() == n, "not one row per element");
  for (double a : k.area) check(finiteNonNegative(a), "bad area");
  check(k.lightTypes.size() == k.lightGroups.size(), "light types and groups differ in number");
  check(k.lightIrradiance.size() == k.lightGroups.size(), "not one E_d array per light");
  for (const std::vector<rad::Rgb>& e : k.lightIrradiance) {
    check(e.size() == n, "not one E_d per element");
    for (const rad::Rgb& c : e) check(valid(c), "bad E_d");
  }
  for (size_t i = 0; i < k.rows.size(); ++i) {
    const rad::FormFactorRow row = k.rows.row(i);
    check(row.values.size() == row.targets.size(), "not one value per target");
    check(row.tinted.empty() || row.tinted.size() == row.targets.size(),
          "not one tinted factor per target");
    check(std::isfinite(row.escaped), "escaped not finite");
    for (size_t t = 0; t < row.targets.size(); ++t) {
      check(row.targets[t] >= 0 && static_cast<size_t>(row.targets[t]) < n, "target out of range");
      check(t == 0 || row.targets[t] > row.targets[t - 1], "targets not increasing");
      check(finiteNonNegative(row.values[t]), "bad factor");
      if (!row.tinted.empty()) check(valid(row.tinted[t]), "bad tinted factor");
    }
  }
  check(k.options.raysPerElement >= 1 && k.options.keepFactors, "bad options");
  check(k.corners.size() == n && k.material.size() == n && k.patch.size() == n &&
            k.rayMultiplier.size() == n,
        "not one corner triple, material, patch and ray multiplier per element");
  check(std::isfinite(k.elementEdge) && k.elementEdge > 0, "bad element edge");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      rad::fuzz::writeTemp("factors.bin", reinterpret_cast<const char*>(data), size);
  const std::optional<rad::KeptFactors> kept = read(path);
  if (!kept) return 0;
  checkKept(*kept);

  // Round trip: what was accepted, written again, reads again to the same.
  const std::string again = (rad::fuzz::tempDir() / "again.bin").string();
  {
    std::ofstream out(again, std::ios::binary | std::ios::trunc);
    rad::writeKeptFactors(out, *kept);
    check(out.good(), "cannot write the kept factors back");
  }
  const std::optional<rad::KeptFactors> back = read(again);
  check(back.has_value(), "the written-back file is refused");
  check(back->area == kept->area, "areas differ after the round trip");
  check(back->rows.size() == kept->rows.size(), "row count differs after the round trip");
  check(back->lightGroups == kept->lightGroups && back->lightTypes == kept->lightTypes,
        "lights differ after the round trip");
  check(back->lightIrradiance.size() == kept->lightIrradiance.size(),
        "light count differs after the round trip");
  for (size_t i = 0; i < kept->rows.size(); ++i) {
    const rad::FormFactorRow a = kept->rows.row(i), b = back->rows.row(i);
    check(b.targets == a.targets, "targets differ after the round trip");
    check(b.values == a.values, "factors differ after the round trip");
    check(b.tinted.size() == a.tinted.size(), "tinted factors differ after the round trip");
  }
  check(back->scenePath == kept->scenePath && back->fingerprint == kept->fingerprint,
        "header differs after the round trip");
  check(back->corners == kept->corners && back->material == kept->material &&
            back->patch == kept->patch && back->rayMultiplier == kept->rayMultiplier &&
            back->elementEdge == kept->elementEdge,
        "the mesh differs after the round trip");
  check(back->lightInput.file == kept->lightInput.file &&
            back->lightInput.shortcuts.size() == kept->lightInput.shortcuts.size(),
        "the light input differs after the round trip");
  return 0;
}
