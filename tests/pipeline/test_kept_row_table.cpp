// KeptRowTable: the kept rows as one compressed-row matrix. What goes in comes out row by row (at
// factors.bin's f32 precision), the matrix the gathering solvers take is F, and moving a table
// hands its storage over (relight relies on it not copying 35 million factors).
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <vector>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/pipeline/kept_row_table.h"

namespace rad {
namespace {

std::vector<FormFactorRow> threeRows() {
  std::vector<FormFactorRow> rows(3);
  rows[0].targets = {1, 2};
  rows[0].values = {0.25, 0.1};  // 0.1 is no float
  rows[0].escaped = 0.65;
  rows[2].targets = {0};
  rows[2].values = {0.5};
  rows[2].escaped = 0.5;
  return rows;
}

TEST(KeptRowTable, GivesBackEachRowAtFloatPrecision) {
  const std::vector<FormFactorRow> in = threeRows();
  const KeptRowTable table(in);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table.factorCount(), 3u);
  for (size_t i = 0; i < in.size(); ++i) {
    const FormFactorRow out = table.row(i);
    EXPECT_EQ(out.targets, in[i].targets) << i;
    EXPECT_EQ(out.escaped, in[i].escaped) << i;
    ASSERT_EQ(out.values.size(), in[i].values.size()) << i;
    for (size_t k = 0; k < out.values.size(); ++k)
      EXPECT_EQ(out.values[k], static_cast<double>(static_cast<float>(in[i].values[k])));
    EXPECT_TRUE(out.tinted.empty());
  }
  EXPECT_NE(table.row(0).values[1], 0.1);
}

TEST(KeptRowTable, TheMatrixIsFRowByRow) {
  KeptRowTable table(threeRows());
  const KeptRowTable::Matrix copy = table.matrix();
  EXPECT_EQ(table.size(), 3u);  // matrix() keeps the table
  const KeptRowTable::Matrix f = table.takeMatrix();
  EXPECT_EQ(table.size(), 0u);  // takeMatrix() empties it
  ASSERT_EQ(f.rows(), 3);
  ASSERT_EQ(f.cols(), 3);
  EXPECT_EQ(f.nonZeros(), 3);
  EXPECT_EQ(f.coeff(0, 1), 0.25);
  EXPECT_EQ(f.coeff(0, 2), static_cast<double>(0.1f));
  EXPECT_EQ(f.coeff(1, 0), 0.0);
  EXPECT_EQ(f.coeff(2, 0), 0.5);
  EXPECT_EQ(copy.coeff(0, 2), f.coeff(0, 2));
}

// Many rows (the constructor copies them side by side in blocks): the same table as appending
// them one by one, as factors.bin's reader does.
TEST(KeptRowTable, BuiltFromRowsIsTheTableOfTheSameRowsAppended) {
  std::vector<FormFactorRow> rows(3000);
  KeptRowTable appended;
  appended.reserve(rows.size(), 3000 * 7);
  for (size_t i = 0; i < rows.size(); ++i) {
    for (int k = 0; k < static_cast<int>(i % 7); ++k) {
      rows[i].targets.push_back(static_cast<int>((i * 13 + 97 * k) % 3000) / 7 * 7 + k);
      rows[i].values.push_back(1.0 / (3.0 + static_cast<double>(i + k)));
    }
    std::sort(rows[i].targets.begin(), rows[i].targets.end());
    rows[i].escaped = 0.001 * static_cast<double>(i % 11);
    const std::vector<float> values(rows[i].values.begin(), rows[i].values.end());
    appended.appendRow(rows[i].targets.data(), values.data(), values.size(), rows[i].escaped, {});
  }
  const KeptRowTable built(rows);
  ASSERT_EQ(built.size(), appended.size());
  ASSERT_EQ(built.factorCount(), appended.factorCount());
  for (size_t i = 0; i < rows.size(); ++i) {
    const FormFactorRow a = built.row(i), b = appended.row(i);
    ASSERT_EQ(a.targets, b.targets) << i;
    ASSERT_EQ(a.values, b.values) << i;
    ASSERT_EQ(a.escaped, b.escaped) << i;
  }
}

// update's table: rows taken from the kept table and renumbered (an element gone, two swapped)
// next to new rows. Each must be what renumbering the kept row by hand gives: the entries of
// the gone element left out, the targets sorted again where the swap unsorted them.
TEST(KeptRowTable, AnUpdatesRowsAreTheKeptRowsRenumberedBesideTheNewOnes) {
  std::vector<FormFactorRow> old(4);
  old[0].targets = {1, 2, 3};
  old[0].values = {0.25, 0.125, 0.0625};
  old[0].escaped = 0.5625;
  old[1].targets = {0, 2};
  old[1].values = {0.5, 0.1};
  old[1].escaped = 0.4;
  old[2].targets = {0, 3};
  old[2].values = {0.375, 0.25};
  old[3].escaped = 1;
  const KeptRowTable kept(old);
  // New elements: 0 is old 0, 1 is old 3, 2 is old 2, 3 is new; old 1 is gone.
  const std::vector<int> newIndexOf = {0, -1, 2, 1};
  std::vector<FormFactorRow> rows(4);
  rows[3].targets = {0, 1};
  rows[3].values = {0.3, 0.2};
  rows[3].escaped = 0.5;
  const std::vector<int> keptFrom = {0, 3, 2, -1};
  const KeptRowTable table(rows, kept, keptFrom, newIndexOf);
  ASSERT_EQ(table.size(), 4u);
  const FormFactorRow r0 = table.row(0), r1 = table.row(1), r2 = table.row(2), r3 = table.row(3);
  EXPECT_EQ(r0.targets, (std::vector<int>{1, 2}));  // old 3 → 1, old 2 → 2, old 1 gone; sorted
  EXPECT_EQ(r0.values, (std::vector<double>{0.0625, 0.125}));
  EXPECT_EQ(r0.escaped, 0.5625);
  EXPECT_TRUE(r1.targets.empty());
  EXPECT_EQ(r1.escaped, 1);
  EXPECT_EQ(r2.targets, (std::vector<int>{0, 1}));
  EXPECT_EQ(r2.values, (std::vector<double>{0.375, 0.25}));
  EXPECT_EQ(r3.targets, (std::vector<int>{0, 1}));
  EXPECT_EQ(r3.values, (std::vector<double>{static_cast<float>(0.3), static_cast<float>(0.2)}));
  EXPECT_EQ(table.factorCount(), 6u);
}

// update's rows brought up to date ray by ray: a kept row of 8 rays, renumbered (two targets
// swapped), with its changes in ray counts merged in: a new target, one whose count falls to 0
// (left out), one that grows, and fewer escaped rays. Each factor is its count over 8.
TEST(KeptRowTable, AnUpdatesChangedRowHasItsChangesMergedIntoTheRenumberedKeptRow) {
  std::vector<FormFactorRow> old(4);
  old[0].targets = {1, 2, 3};
  old[0].values = {2.0 / 8, 1.0 / 8, 3.0 / 8};
  old[0].escaped = 2.0 / 8;
  const KeptRowTable kept(old);
  const std::vector<int> newIndexOf = {0, 1, 3, 2};  // old 2 and 3 swap places
  RowChanges changes;
  changes.counted = 8;
  changes.escaped = -1;
  changes.counts = {{0, 1}, {2, -3}, {3, 3}};  // new numbering: old 3 is 2, old 2 is 3
  std::vector<RowChanges> all(4);
  all[0] = changes;
  const KeptRowTable table(std::vector<FormFactorRow>(4), kept, {0, 1, 2, 3}, newIndexOf, all);
  const FormFactorRow r = table.row(0);
  EXPECT_EQ(r.targets, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(r.values, (std::vector<double>{1.0 / 8, 2.0 / 8, 4.0 / 8}));
  EXPECT_EQ(r.escaped, 1.0 / 8);
  EXPECT_EQ(table.factorCount(), 3u);
  // A change that would take a count below zero is refused before it gets here: a check.
  all[0].counts = {{1, -3}};
  EXPECT_THROW(KeptRowTable(std::vector<FormFactorRow>(4), kept, {0, 1, 2, 3}, newIndexOf, all),
               CheckFailure);
}

// update lends F to Gauss–Seidel and keeps the table for factors.bin: the matrix comes back as
// it went, and the rows cannot be read while it is away.
TEST(KeptRowTable, ALentMatrixComesBackAndTheRowsWithIt) {
  KeptRowTable table(threeRows());
  KeptRowTable::Matrix f = table.lendMatrix();
  EXPECT_EQ(f.rows(), 3);
  EXPECT_EQ(f.coeff(0, 1), 0.25);
  EXPECT_EQ(table.size(), 3u);
  EXPECT_THROW(table.row(0), CheckFailure);
  EXPECT_THROW(table.lendMatrix(), CheckFailure);
  table.returnMatrix(std::move(f));
  EXPECT_EQ(table.row(0).targets, threeRows()[0].targets);
  EXPECT_EQ(table.row(2).values[0], 0.5);
  KeptRowTable::Matrix other(2, 2);
  EXPECT_THROW(table.returnMatrix(std::move(other)), CheckFailure);
}

TEST(KeptRowTable, MovingHandsTheStorageOver) {
  KeptRowTable a(threeRows());
  KeptRowTable b(std::move(a));
  EXPECT_EQ(b.size(), 3u);
  // Left empty, factors included: Eigen's own "move" would have copied them and left them.
  EXPECT_EQ(a.size(), 0u);         // NOLINT(bugprone-use-after-move)
  EXPECT_EQ(a.factorCount(), 0u);  // NOLINT(bugprone-use-after-move)
  KeptRowTable c;
  c = std::move(b);
  EXPECT_EQ(c.size(), 3u);
  EXPECT_EQ(c.row(2).values, std::vector<double>{0.5});
}

TEST(KeptRowTable, TintedRowsHaveNoOneMatrix) {
  std::vector<FormFactorRow> rows = threeRows();
  rows[2].tinted = {{0.5, 0.25, 0.125}};
  KeptRowTable table(rows);
  EXPECT_TRUE(table.anyTinted());
  EXPECT_EQ(table.row(2).tinted.size(), 1u);
  EXPECT_EQ(table.row(2).tinted[0].g, 0.25);
  EXPECT_THROW(table.takeMatrix(), InputError);
}

// The reader faults the reserved arrays in from a second thread while it appends rows into them
// (populateReserved): that must leave every row as appended, before and after.
TEST(KeptRowTable, PopulatingTheReserveBesideTheAppendsChangesNoRow) {
  constexpr int kRows = 2000, kPerRow = 600;  // 1.2 million factors: many pages
  KeptRowTable table;
  table.reserve(kRows, static_cast<size_t>(kRows) * kPerRow);
  std::thread populating([&table] { table.populateReserved(); });
  std::vector<int32_t> targets(kPerRow);
  std::vector<float> values(kPerRow);
  for (int r = 0; r < kRows; ++r) {
    for (int k = 0; k < kPerRow; ++k) {
      targets[k] = (r + 3 * k) % kRows;
      values[k] = 1.0f / static_cast<float>(1 + r + k);
    }
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    table.appendRow(targets.data(), values.data(), targets.size(), 0.5, {});
    targets.resize(kPerRow);
  }
  populating.join();
  ASSERT_EQ(table.size(), static_cast<size_t>(kRows));
  for (int r = 0; r < kRows; r += 97) {
    const FormFactorRow row = table.row(r);
    ASSERT_FALSE(row.targets.empty());
    for (size_t k = 0; k < row.targets.size(); ++k)
      ASSERT_EQ(row.values[k], static_cast<double>(1.0f / static_cast<float>(1 + r + k)))
          << "row " << r << " factor " << k;
  }
}

}  // namespace
}  // namespace rad
