// solution.vtp, read back with VTK's own reader, holds the elements.csv solution exactly.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "radiosity/core/errors.h"
#include "tests/support/run_command.h"
#include "viewer/solution_vtp.h"

namespace rad {
namespace {

const std::string cornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

std::vector<std::vector<double>> readCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    std::string field;
    // The 16 numeric columns (buried_cells, hexadecimal, follows).
    while (row.size() < 16 && std::getline(s, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

class SolutionVtp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(testing::scratchPath("vtp"));
    const auto r = testing::runRadiosity(
        "solve " + cornell + " --elements 300 --rays 64 --quiet --out " + dir_->string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  static std::filesystem::path* dir_;
};
std::filesystem::path* SolutionVtp::dir_ = nullptr;

TEST_F(SolutionVtp, HoldsTheElementsCsvSolution) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((*dir_ / "solution.vtp").c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  const auto csv = readCsv(*dir_ / "elements.csv");
  ASSERT_GT(csv.size(), 100u);
  ASSERT_EQ(data->GetNumberOfCells(), static_cast<vtkIdType>(csv.size()));
  ASSERT_EQ(data->GetNumberOfPolys(), data->GetNumberOfCells());

  vtkCellData* cd = data->GetCellData();
  for (const char* name : {"B", "radiance", "unshot", "area", "patch", "material", "level"})
    ASSERT_NE(cd->GetArray(name), nullptr) << name;
  ASSERT_EQ(cd->GetArray("B")->GetNumberOfComponents(), 3);
  ASSERT_EQ(cd->GetArray("radiance")->GetNumberOfComponents(), 3);
  ASSERT_EQ(cd->GetArray("unshot")->GetNumberOfComponents(), 3);
  ASSERT_NE(data->GetPointData()->GetArray("radiance"), nullptr);

  // csv: element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b; doubles in both
  // files, 17 significant digits in the csv: equal to the last bit.
  for (size_t e = 0; e < csv.size(); ++e) {
    const auto& row = csv[e];
    const vtkIdType id = static_cast<vtkIdType>(e);
    EXPECT_EQ(cd->GetArray("patch")->GetComponent(id, 0), row[1]);
    EXPECT_EQ(cd->GetArray("material")->GetComponent(id, 0), row[2]);
    EXPECT_EQ(cd->GetArray("area")->GetComponent(id, 0), row[3]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(cd->GetArray("B")->GetComponent(id, c), row[10 + c]) << "element " << e;
      EXPECT_EQ(cd->GetArray("radiance")->GetComponent(id, c), row[13 + c]) << "element " << e;
    }
    // The cell is the element: its centroid is the csv's.
    double p[3][3];
    const vtkIdType* ids = nullptr;
    vtkIdType n = 0;
    data->GetCellPoints(id, n, ids);
    ASSERT_EQ(n, 3);
    for (int k = 0; k < 3; ++k) data->GetPoint(ids[k], p[k]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR((p[0][c] + p[1][c] + p[2][c]) / 3, row[4 + c], 1e-12);
    EXPECT_GE(cd->GetArray("level")->GetComponent(id, 0), 0);
  }
}

TEST_F(SolutionVtp, UnshotPowerIsWhatTheSolverLeft) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((*dir_ / "solution.vtp").c_str());
  reader->Update();
  vtkDataArray* unshot = reader->GetOutput()->GetCellData()->GetArray("unshot");
  double total = 0;
  for (vtkIdType e = 0; e < unshot->GetNumberOfTuples(); ++e)
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(unshot->GetComponent(e, c), 0.0);
      total += unshot->GetComponent(e, c);
    }
  std::ifstream in(*dir_ / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  // The progressive solver's measure is exactly unshot power over emitted power.
  const double emitted = summary["solver"]["emitted_power"];
  EXPECT_NEAR(total / emitted, summary["solver"]["final"].get<double>(), 1e-9);
  EXPECT_LE(total / emitted, summary["solver"]["tolerance"].get<double>());
}

TEST_F(SolutionVtp, VertexRadianceIsTheAreaWeightedMeanOfItsElements) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((*dir_ / "solution.vtp").c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  vtkDataArray* area = data->GetCellData()->GetArray("area");
  vtkDataArray* radiance = data->GetCellData()->GetArray("radiance");
  std::vector<double> sum(3 * data->GetNumberOfPoints(), 0.0),
      weight(data->GetNumberOfPoints(), 0.0);
  for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
    const vtkIdType* ids = nullptr;
    vtkIdType n = 0;
    data->GetCellPoints(cell, n, ids);
    for (vtkIdType k = 0; k < n; ++k) {
      weight[ids[k]] += area->GetComponent(cell, 0);
      for (int c = 0; c < 3; ++c)
        sum[3 * ids[k] + c] += area->GetComponent(cell, 0) * radiance->GetComponent(cell, c);
    }
  }
  vtkDataArray* points = data->GetPointData()->GetArray("radiance");
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p) {
    ASSERT_GT(weight[p], 0.0) << "point " << p << " belongs to no element";
    for (int c = 0; c < 3; ++c) {
      const double expected = sum[3 * p + c] / weight[p];
      EXPECT_NEAR(points->GetComponent(p, c), expected, 1e-12 * (1 + std::abs(expected)));
    }
  }
}

TEST_F(SolutionVtp, ReadBackByTheViewerChecksArrays) {
  vtkSmartPointer<vtkPolyData> data = readSolutionVtp((*dir_ / "solution.vtp").string());
  EXPECT_EQ(solutionSceneFile(data), cornell);
  EXPECT_THROW(readSolutionVtp((*dir_ / "missing.vtp").string()), InputError);
  // A PolyData without the solution's arrays is rejected, naming the file.
  const auto bad = *dir_ / "bad.vtp";
  data->GetCellData()->RemoveArray("unshot");
  {
    std::ofstream out(bad, std::ios::binary);
    writeSolutionVtp(out, data);
  }
  try {
    readSolutionVtp(bad.string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("unshot"), std::string::npos) << e.what();
  }
}

// What VTK's reader lets through but the viewer cannot use: each is refused naming the file and
// what is wrong, where the viewer would otherwise index past its arrays or size tables by it.
TEST_F(SolutionVtp, ReadBackRefusesValuesTheViewerCannotUse) {
  struct Case {
    const char* name;
    const char* expected;  // in the message
    void (*spoil)(vtkPolyData*);
  };
  const Case cases[] = {
      {"point_out_of_range", "names point",
       [](vtkPolyData* d) {
         d->GetPolys()->GetConnectivityArray()->SetComponent(4, 0, d->GetNumberOfPoints());
       }},
      {"negative_point", "names point",
       [](vtkPolyData* d) { d->GetPolys()->GetConnectivityArray()->SetComponent(0, 0, -1); }},
      {"nan_radiosity", "'B'",
       [](vtkPolyData* d) { d->GetCellData()->GetArray("B")->SetComponent(7, 1, std::nan("")); }},
      {"negative_area", "'area'",
       [](vtkPolyData* d) { d->GetCellData()->GetArray("area")->SetComponent(3, 0, -1e-3); }},
      {"infinite_point", "not finite",
       [](vtkPolyData* d) { d->GetPoints()->SetPoint(2, 0, HUGE_VAL, 0); }},
      {"negative_patch", "'patch'",
       [](vtkPolyData* d) { d->GetCellData()->GetArray("patch")->SetComponent(5, 0, -2); }},
  };
  for (const Case& c : cases) {
    vtkSmartPointer<vtkPolyData> data = readSolutionVtp((*dir_ / "solution.vtp").string());
    c.spoil(data);
    const auto bad = *dir_ / (std::string(c.name) + ".vtp");
    {
      std::ofstream out(bad, std::ios::binary);
      writeSolutionVtp(out, data);
    }
    try {
      readSolutionVtp(bad.string());
      ADD_FAILURE() << c.name << ": accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace rad
