// update after a geometry edit: the short block of the Cornell box moved. Rows whose rays meet
// neither the block's old nor its new place are the rows a fresh solve casts (same random
// streams, same BVH frame), so the updated rows must equal a fresh solve's exactly, and its
// solution must equal the fresh solve's to the solver's tolerance, while reusing a stated share
// of the rows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/incremental_update.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/kept_factors_stage.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/solvers/progressive_solver.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(RADIOSITY_DATA_DIR) / "cornell_box";

const char* const kOneLamp = R"({"lights": [{"type": "point", "position": [0.45, 0.45, 0.1],
                                  "intensity": [0.3, 0.18, 0.06]}]})";

// The Cornell box OBJ with the short block's 8 vertices (the 8 lines after "o short_block")
// shifted by dx along x; a lights file beside it.
void writeCornell(const fs::path& dir, double dx, const char* lights = kOneLamp) {
  fs::create_directories(dir);
  fs::copy_file(kData / "cornell_box.mtl", dir / "cornell_box.mtl",
                fs::copy_options::overwrite_existing);
  std::ifstream in(kData / "cornell_box.obj");
  std::ofstream out(dir / "cornell_box.obj");
  std::string line;
  int shortBlockVertices = -1;
  while (std::getline(in, line)) {
    if (line == "o short_block") shortBlockVertices = 0;
    if (shortBlockVertices >= 0 && shortBlockVertices < 8 && line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      double x, y, z;
      v >> x >> y >> z;
      std::ostringstream moved;
      moved.precision(17);
      moved << "v " << x + dx << " " << y << " " << z;
      line = moved.str();
      ++shortBlockVertices;
    }
    out << line << "\n";
  }
  ASSERT_EQ(shortBlockVertices, 8);
  std::ofstream(dir / "cornell_box.lights.json") << lights;
}

SolveOptions options(const fs::path& dir) {
  SolveOptions o;
  o.scenePath = (dir / "cornell_box.obj").string();
  o.elementSize = 0.06;
  o.raysPerElement = 64;
  o.threads = 2;
  o.solver = SolverKind::GaussSeidel;
  o.tolerance = 1e-10;
  o.maxIterations = 100000;
  o.keepFactors = true;
  return o;
}

double peak(const std::vector<Rgb>& v) {
  double p = 0;
  for (const Rgb& c : v) p = std::max(p, c.maxComponent());
  return p;
}

// Every row of `a` is `b`'s: the same targets, factors and escaped fraction.
void expectSameRows(const KeptRowTable& a, const KeptRowTable& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t e = 0; e < a.size(); ++e) {
    const FormFactorRow x = a.row(e), y = b.row(e);
    ASSERT_EQ(x.targets, y.targets) << "element " << e;
    for (size_t k = 0; k < x.values.size(); ++k) ASSERT_DOUBLE_EQ(x.values[k], y.values[k]);
    ASSERT_DOUBLE_EQ(x.escaped, y.escaped) << "element " << e;
  }
}

class IncrementalUpdate : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("radiosity_update_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // What elements.csv keeps of a solve, as `update` reads it back: B, E_d and the buried cells.
  static PreviousSolution previousOf(const SolveResult& solve) {
    PreviousSolution previous;
    previous.radiosity = solve.solution.radiosity;
    previous.directIrradiance = solve.solution.directIrradiance;
    if (solve.solution.exposure)
      previous.buriedCells =
          solve.solution.exposure->allBuriedCells(solve.solution.mesh->elementCount());
    return previous;
  }
  // The user's edit: a kept solve of the scene `writeBefore` writes, the scene rewritten by
  // `writeAfter` and brought up to date by update, and a fresh solve of the same edited scene.
  struct Edited {
    SolveResult before, updated, reference;
  };
  Edited solveEditAndUpdate(
      const std::function<void(const fs::path&)>& writeBefore,
      const std::function<void(const fs::path&)>& writeAfter,
      const std::function<SolveOptions(const fs::path&)>& optionsFor = options) {
    const fs::path scene = dir_ / "scene", fresh = dir_ / "fresh";
    writeBefore(scene);
    SolveResult before = runSolve(optionsFor(scene));
    if (!before.kept) throw std::runtime_error("the solve kept no factors");
    writeAfter(scene);
    writeAfter(fresh);
    // The buried cells as elements.csv keeps them: the update keeps those the edit cannot change.
    if (!before.solution.exposure) throw std::runtime_error("the solve kept no exposure");
    SolveResult updated =
        updateKeptSolve(*before.kept, "kept", previousOf(before), optionsFor(scene));
    SolveResult reference = runSolve(optionsFor(fresh));
    // Kept or probed again, every element's buried cells are the fresh solve's.
    const int n = updated.solution.mesh->elementCount();
    EXPECT_EQ(n, reference.solution.mesh->elementCount());
    for (int e = 0; e < n && e < reference.solution.mesh->elementCount(); ++e)
      EXPECT_EQ(updated.solution.exposure->buriedCells(e),
                reference.solution.exposure->buriedCells(e))
          << "element " << e;
    return {std::move(before), std::move(updated), std::move(reference)};
  }
  fs::path dir_;
};

TEST_F(IncrementalUpdate, MovedBlockEqualsAFreshSolveAndReusesTheRowsItCannotChange) {
  // The user moves the short block 5 cm towards the red wall.
  const auto [before, updated, reference] =
      solveEditAndUpdate([](const fs::path& d) { writeCornell(d, 0); },
                         [](const fs::path& d) { writeCornell(d, -0.05); });
  ASSERT_TRUE(before.kept);

  const int n = updated.solution.mesh->elementCount();
  ASSERT_EQ(n, reference.solution.mesh->elementCount());
  const SolveReport::Update& u = updated.report.update;
  EXPECT_EQ(u.moved, u.removed);  // the block's elements, moved: as many gone as new
  EXPECT_GT(u.moved, 0);
  // Every row, reused or cast again, is the row the fresh solve cast.
  expectSameRows(updated.kept->rows, reference.kept->rows);
  if (HasFatalFailure()) return;
  // Equal solutions, to the solvers' tolerance; the edit itself moves light by far more.
  const std::vector<Rgb>& a = updated.solution.radiosity;
  const std::vector<Rgb>& b = reference.solution.radiosity;
  const double scale = peak(b);
  double changedMost = 0;
  for (int e = 0; e < n; ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(a[e][c], b[e][c], 1e-7 * scale) << "element " << e;
      changedMost = std::max(changedMost, std::abs(b[e][c] - before.solution.radiosity[e][c]));
    }
  EXPECT_GT(changedMost, 0.05 * scale);
  // The stated share: in this box the block is in view of nearly every surface, so most rows have
  // a ray that meets its old or new place first; those are brought up to date ray by ray, and
  // only the block's own rows and those whose exposed area changed are cast again.
  EXPECT_EQ(u.rowsReused + u.rowsUpdated + updated.report.rowsComputed, n);
  EXPECT_GT(u.rowsUpdated, n / 2);
  EXPECT_LE(updated.report.rowsComputed, u.moved + u.rowsOtherChange);
  EXPECT_LT(u.rowsOtherChange, n / 20);
  // Far fewer rays changed than a recast of the rows would cast.
  EXPECT_LT(u.raysChanged, static_cast<uint64_t>(u.rowsUpdated) * 64 / 4);
  EXPECT_GT(u.rowsOtherChange, 0);  // the floor under the block's old and new footprint
  // The buried cells: kept where no probe ray can meet the block's old or new place, probed
  // again around it (the floor under its footprints, which the helper compares with the fresh
  // solve's).
  EXPECT_GT(u.buriedCellsKept, 0);
  EXPECT_LT(u.buriedCellsKept, n - u.moved);
}

// A courtyard: a 12 m × 12 m floor and a 3 m wall along its back, lit by a sky, and a 0.4 m box
// near one corner moved by dx along x. Seen from most of the floor the box is small: the rows'
// rays whose direction strata cannot point at it are not made at all.
void writeCourtyard(const fs::path& dir, double dx) {
  fs::create_directories(dir);
  std::ofstream out(dir / "courtyard.obj");
  out.precision(17);
  out << "v -6 0 -6\nv -6 0 6\nv 6 0 6\nv 6 0 -6\nf 1 2 3 4\n";
  out << "v -6 0 -6\nv 6 0 -6\nv 6 3 -6\nv -6 3 -6\nf 5 6 7 8\n";
  const double x0 = -4.5 + dx, z0 = -4.5, s = 0.4;
  for (int k = 0; k < 8; ++k)
    out << "v " << x0 + s * (k & 1) << " " << s * ((k >> 1) & 1) << " " << z0 + s * ((k >> 2) & 1)
        << "\n";
  // Outward faces of the box (vertices 9…16: bit 0 x, bit 1 y, bit 2 z).
  out << "f 9 13 15 11\nf 10 12 16 14\nf 9 10 14 13\nf 11 15 16 12\nf 9 11 12 10\n"
         "f 13 14 16 15\n";
  std::ofstream(dir / "courtyard.lights.json")
      << R"({"lights": [{"type": "sky", "radiance": [0.4, 0.5, 0.7]}]})";
}

TEST_F(IncrementalUpdate, RaysPointingAwayFromASmallEditAreNotMadeAndTheRowsStayExact) {
  auto courtyard = [](const fs::path& dir) {
    SolveOptions o = options(dir);
    o.scenePath = (dir / "courtyard.obj").string();
    o.elementSize = 0.5;
    return o;
  };
  const auto [before, updated, reference] =
      solveEditAndUpdate([](const fs::path& d) { writeCourtyard(d, 0); },
                         [](const fs::path& d) { writeCourtyard(d, 0.3); }, courtyard);
  const int n = updated.solution.mesh->elementCount();
  ASSERT_EQ(n, reference.solution.mesh->elementCount());
  expectSameRows(updated.kept->rows, reference.kept->rows);
  if (HasFatalFailure()) return;
  const SolveReport::Update& u = updated.report.update;
  EXPECT_GT(u.rowsUpdated, 0);
  EXPECT_GT(u.raysChanged, 0u);
  // Most rows are far from the box, and only their few strata that point at it are made.
  EXPECT_LT(u.raysTested, u.raysOfKeptRows / 4);
  EXPECT_GE(u.raysTested, u.raysChanged);
}

// The lights' first shot: an element keeps its kept E_d from a light only where none of its
// shadow rays to it can meet the block's old or new place, so every element's E_d from every
// light must be the fresh solve's, bit for bit (same strata, same random streams), while a share
// of them is kept for each kind of light. The sun and the sky come in through the open front.
TEST_F(IncrementalUpdate, DirectLightIsKeptOnlyWhereTheEditCannotShadowIt) {
  const char* const lights = R"({"lights": [
      {"type": "point", "position": [0.45, 0.45, 0.1], "intensity": [0.3, 0.18, 0.06]},
      {"type": "directional", "direction": [0.3, -0.5, 1], "irradiance": [2, 2, 1.6],
       "angular_diameter_degrees": 0.53},
      {"type": "sky", "radiance": [0.2, 0.3, 0.5]}]})";
  const auto [before, updated, reference] =
      solveEditAndUpdate([&](const fs::path& d) { writeCornell(d, 0, lights); },
                         [&](const fs::path& d) { writeCornell(d, -0.05, lights); });
  const size_t n = static_cast<size_t>(updated.solution.mesh->elementCount());
  ASSERT_EQ(updated.kept->lightIrradiance.size(), 3u);
  int64_t keptPairs = 0;
  for (size_t l = 0; l < 3; ++l) {
    SCOPED_TRACE("light " + std::to_string(l));
    const std::vector<Rgb>& a = updated.kept->lightIrradiance[l];
    const std::vector<Rgb>& b = reference.kept->lightIrradiance[l];
    const std::vector<Rgb>& old = before.kept->lightIrradiance[l];
    ASSERT_EQ(a.size(), n);
    int unchanged = 0, changed = 0;
    for (size_t e = 0; e < n; ++e) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(a[e][c], b[e][c]) << "element " << e;
      const bool same = a[e].r == old[e].r && a[e].g == old[e].g && a[e].b == old[e].b;
      (same ? unchanged : changed) += 1;
    }
    // The edit shadows some elements anew from each light, and leaves most alone.
    EXPECT_GT(changed, 0);
    EXPECT_GT(unchanged, static_cast<int>(n) / 2);
    keptPairs += unchanged;
  }
  // Kept where the rays cannot meet the edit: never more than the unchanged values, and for
  // these lights, which see the block from most of the box, well over a tenth of all pairs.
  const int64_t kept = updated.report.update.directLightKept;
  EXPECT_LE(kept, keptPairs);
  EXPECT_GT(kept, static_cast<int64_t>(3 * n) / 10);
  EXPECT_LT(updated.report.directLightRays, reference.report.directLightRays);
  const double scale = peak(reference.solution.radiosity);
  for (size_t e = 0; e < n; ++e)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(updated.solution.radiosity[e][c], reference.solution.radiosity[e][c],
                  1e-7 * scale);
}

// A lamp moved in the lights file (the same number of lights) with the block: the kept direct
// light is from the old lamp, so none of it may be kept, even where the new lamp's rays miss the
// block; every element's must be the fresh solve's.
TEST_F(IncrementalUpdate, DirectLightIsCastAgainWhenALightChanged) {
  const char* const moved = R"({"lights": [{"type": "point", "position": [0.2, 0.45, 0.3],
                                "intensity": [0.3, 0.18, 0.06]}]})";
  const auto [before, updated, reference] =
      solveEditAndUpdate([](const fs::path& d) { writeCornell(d, 0); },
                         [&](const fs::path& d) { writeCornell(d, -0.05, moved); });
  EXPECT_EQ(updated.report.update.directLightKept, 0);
  const std::vector<Rgb>& a = updated.kept->lightIrradiance[0];
  const std::vector<Rgb>& b = reference.kept->lightIrradiance[0];
  ASSERT_EQ(a.size(), b.size());
  for (size_t e = 0; e < a.size(); ++e)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(a[e][c], b[e][c]) << "element " << e;
}

// The Cornell box with a 10 cm crate on its floor as the file's first object: every element of
// the box comes after the crate's and is renumbered by adding it. Its random streams follow the
// element, not its index (elementStream), so every row and every light's direct light of the
// update must still be the fresh solve's, bit for bit, and the renumbered rows are brought up to
// date, not cast again. The crate's bottom lies on the floor: a ray that met the floor there
// before must find it again under the crate (not skip it with the bottom face).
void writeCornellWithCrateFirst(const fs::path& dir, const char* lights) {
  writeCornell(dir, 0, lights);
  std::ifstream in(dir / "cornell_box.obj");
  std::ostringstream out;
  out.precision(17);
  out << "mtllib cornell_box.mtl\no crate\n";
  const double x0 = 0.4, z0 = 0.42, s = 0.1;
  for (int k = 0; k < 8; ++k)  // bit 0: x, bit 1: y, bit 2: z
    out << "v " << x0 + s * (k & 1) << " " << s * ((k >> 1) & 1) << " " << z0 + s * ((k >> 2) & 1)
        << "\n";
  out << "usemtl white\nf 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("f ", 0) == 0) {  // the box's own vertices now come after the crate's 8
      std::istringstream f(line.substr(2));
      line = "f";
      for (int v; f >> v;) line += " " + std::to_string(v + 8);
    }
    out << line << "\n";
  }
  in.close();
  std::ofstream(dir / "cornell_box.obj") << out.str();
}

TEST_F(IncrementalUpdate, ACrateAddedAheadOfEveryElementLeavesTheRenumberedRowsExact) {
  const char* const lights = R"({"lights": [
      {"type": "point", "position": [0.45, 0.45, 0.1], "intensity": [0.3, 0.18, 0.06]},
      {"type": "directional", "direction": [0.3, -0.5, 1], "irradiance": [2, 2, 1.6],
       "angular_diameter_degrees": 0.53}]})";
  const auto [before, updated, reference] =
      solveEditAndUpdate([&](const fs::path& d) { writeCornell(d, 0, lights); },
                         [&](const fs::path& d) { writeCornellWithCrateFirst(d, lights); });
  const int n = updated.solution.mesh->elementCount();
  ASSERT_EQ(n, reference.solution.mesh->elementCount());
  const SolveReport::Update& u = updated.report.update;
  EXPECT_EQ(u.removed, 0);
  ASSERT_GT(u.moved, 0);  // the crate's elements, numbered first
  EXPECT_EQ(n, before.solution.mesh->elementCount() + u.moved);
  // Every row is the fresh solve's: with streams by element index, every renumbered row the crate
  // can change would differ.
  expectSameRows(updated.kept->rows, reference.kept->rows);
  if (HasFatalFailure()) return;
  for (size_t l = 0; l < 2; ++l)
    for (int e = 0; e < n; ++e)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(updated.kept->lightIrradiance[l][static_cast<size_t>(e)][c],
                  reference.kept->lightIrradiance[l][static_cast<size_t>(e)][c])
            << "light " << l << ", element " << e;
  // Only the crate's rows, those of the floor it stands on (their exposed area changed) and those
  // whose ray budget changed are cast again (an emitter's or a lit element's budget follows its
  // share of the power, and the crate adds 2.7% more elements to share it); the other renumbered
  // rows are reused or updated ray by ray.
  EXPECT_EQ(u.rowsReused + u.rowsUpdated + updated.report.rowsComputed, n);
  EXPECT_LE(updated.report.rowsComputed, u.moved + u.rowsOtherChange);
  EXPECT_LT(u.rowsOtherChange, n / 6);
  EXPECT_GT(u.rowsUpdated, n / 4);
  const double scale = peak(reference.solution.radiosity);
  for (int e = 0; e < n; ++e)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(updated.solution.radiosity[e][c], reference.solution.radiosity[e][c],
                  1e-7 * scale);
}

TEST_F(IncrementalUpdate, UnchangedSceneReusesEveryRowAndKeepsItsSolution) {
  const fs::path scene = dir_ / "scene";
  writeCornell(scene, 0);
  const SolveResult before = runSolve(options(scene));
  const SolveResult updated =
      updateKeptSolve(*before.kept, "kept", previousOf(before), options(scene));
  EXPECT_EQ(updated.report.update.rowsReused, updated.solution.mesh->elementCount());
  EXPECT_EQ(updated.report.rowsComputed, 0);
  EXPECT_EQ(updated.report.update.moved, 0);
  // Nothing moved and the lights are as they were: every element keeps its direct light.
  EXPECT_EQ(updated.report.update.directLightKept, updated.solution.mesh->elementCount());
  EXPECT_EQ(updated.report.directLightRays, 0u);
  const double scale = peak(before.solution.radiosity);
  for (size_t e = 0; e < updated.solution.radiosity.size(); ++e)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(updated.solution.radiosity[e][c], before.solution.radiosity[e][c], 1e-7 * scale);
}

// An update that finds no edit gives the kept solution back bit for bit, whichever solver made it:
// a progressive solve's rows are used the other way round from a Gauss–Seidel one's, so solving
// again from it would move every element by the two estimates' difference.
TEST_F(IncrementalUpdate, UnchangedSceneGivesAProgressiveSolveBackBitForBit) {
  const fs::path scene = dir_ / "scene";
  writeCornell(scene, 0);
  SolveOptions progressive = options(scene);
  progressive.solver = SolverKind::Progressive;
  progressive.tolerance = 1e-3;
  const SolveResult before = runSolve(progressive);
  ASSERT_TRUE(before.kept);
  const SolveResult updated =
      updateKeptSolve(*before.kept, "kept", previousOf(before), options(scene));
  ASSERT_EQ(updated.solution.radiosity.size(), before.solution.radiosity.size());
  ASSERT_EQ(updated.solution.directIrradiance.size(), before.solution.directIrradiance.size());
  for (size_t e = 0; e < before.solution.radiosity.size(); ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(updated.solution.radiosity[e][c], before.solution.radiosity[e][c]) << e;
      ASSERT_EQ(updated.solution.directIrradiance[e][c], before.solution.directIrradiance[e][c])
          << e;
    }
  EXPECT_EQ(updated.report.iterations, 0);
}

// A colour changed with no geometry moved is no edit of the rows, but it is of the solution: the
// update solves again and gives the fresh solve's answer.
TEST_F(IncrementalUpdate, ChangedColourIsSolvedAgainThoughNoRowChanged) {
  const fs::path scene = dir_ / "scene", fresh = dir_ / "fresh";
  writeCornell(scene, 0);
  const SolveResult before = runSolve(options(scene));
  ASSERT_TRUE(before.kept);
  for (const fs::path& d : {scene, fresh}) {
    if (d == fresh) writeCornell(fresh, 0);
    std::ifstream in(d / "cornell_box.mtl");
    std::stringstream text;
    text << in.rdbuf();
    in.close();
    std::string mtl = text.str();
    // Every diffuse colour halved: the light reflected changes everywhere.
    std::string out;
    std::istringstream lines(mtl);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("Kd ", 0) == 0) {
        std::istringstream kd(line.substr(3));
        double r, g, b;
        kd >> r >> g >> b;
        std::ostringstream halved;
        halved.precision(17);
        halved << "Kd " << r / 2 << " " << g / 2 << " " << b / 2;
        line = halved.str();
      }
      out += line + "\n";
    }
    std::ofstream(d / "cornell_box.mtl") << out;
  }
  const SolveResult updated =
      updateKeptSolve(*before.kept, "kept", previousOf(before), options(scene));
  const SolveResult reference = runSolve(options(fresh));
  EXPECT_GT(updated.report.iterations, 0);
  const double scale = peak(reference.solution.radiosity);
  double largestChange = 0;
  for (size_t e = 0; e < updated.solution.radiosity.size(); ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(updated.solution.radiosity[e][c], reference.solution.radiosity[e][c],
                  1e-7 * scale);
      largestChange = std::max(largestChange, std::abs(updated.solution.radiosity[e][c] -
                                                       before.solution.radiosity[e][c]));
    }
  EXPECT_GT(largestChange, 1e-3 * scale);  // the halved colours did change the solution
}

// A progressive solve's converged solution owes almost nothing when shooting starts from it
// (its unshot power is what is left of its tolerance), and moving the block, the update's
// progressive solve from the solution before the edit gives the fresh progressive solve's answer.
TEST_F(IncrementalUpdate, ProgressiveUpdateEqualsAFreshProgressiveSolve) {
  auto progressive = [](const fs::path& dir) {
    SolveOptions o = options(dir);
    o.solver = SolverKind::Progressive;
    o.tolerance = 1e-9;
    return o;
  };
  writeCornell(dir_ / "before", 0);
  const SolveResult before = runSolve(progressive(dir_ / "before"));
  {
    KeptRows rows(*before.kept);
    ProgressiveSolver again(before.solution.problem, rows);
    again.startFrom(before.solution.radiosity);
    EXPECT_LT(again.progress(), 1e-8);
    PreviousSolution previous = previousOf(before);
    previous.directIrradiance.clear();  // no shortcut: solve from it
    const SolveResult same =
        updateKeptSolve(*before.kept, "kept", previous, progressive(dir_ / "before"));
    const double scale = peak(before.solution.radiosity);
    for (size_t e = 0; e < before.solution.radiosity.size(); ++e)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(same.solution.radiosity[e][c], before.solution.radiosity[e][c], 1e-6 * scale)
            << "unchanged, element " << e;
  }
  const Edited edited =
      solveEditAndUpdate([](const fs::path& d) { writeCornell(d, 0); },
                         [](const fs::path& d) { writeCornell(d, 0.05); }, progressive);
  const double scale = peak(edited.reference.solution.radiosity);
  for (size_t e = 0; e < edited.reference.solution.radiosity.size(); ++e)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(edited.updated.solution.radiosity[e][c],
                  edited.reference.solution.radiosity[e][c], 1e-6 * scale)
          << "element " << e;
}

TEST_F(IncrementalUpdate, RefusesWhatItCannotHonour) {
  const fs::path scene = dir_ / "scene";
  writeCornell(scene, 0);
  const SolveResult before = runSolve(options(scene));
  PreviousSolution wrongSize;
  wrongSize.radiosity.resize(before.solution.radiosity.size() + 1);
  EXPECT_THROW(updateKeptSolve(*before.kept, "kept", wrongSize, options(scene)), InputError);
  // Southwell shoots along the gathering matrix's columns: it cannot start from a solution.
  SolveOptions southwell = options(scene);
  southwell.solver = SolverKind::Southwell;
  EXPECT_THROW(updateKeptSolve(*before.kept, "kept", previousOf(before), southwell), InputError);
  // A lamp added: the lights are not what update follows.
  std::ofstream(scene / "cornell_box.lights.json")
      << R"({"lights": [{"type": "point", "position": [0.45, 0.45, 0.1], "intensity": [1, 1, 1]},
                        {"type": "point", "position": [0.2, 0.45, 0.1], "intensity": [1, 1, 1]}]})";
  try {
    updateKeptSolve(*before.kept, "kept", previousOf(before), options(scene));
    FAIL() << "a changed light count must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lights"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rad
