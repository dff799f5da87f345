// The layout check in front of VTK's XML reader (viewer/solution_vtp_layout.h): the writer's own
// files pass, and every departure from them, in the XML or in the compressed blocks, is refused
// naming the file (and the line of the element) before VTK reads a byte. Among them the file
// that crashed VTK 9.1's reader (a String array with more strings than NumberOfTuples), here in
// the writer's own binary format.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "radiosity/core/errors.h"
#include "tests/support/closed_cube.h"
#include "viewer/solution_polydata.h"
#include "viewer/solution_vtp.h"
#include "viewer/solution_vtp_layout.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

fs::path scratchFile(const std::string& name) {
  return fs::temp_directory_path() /
         ("radiosity_layout_" + std::to_string(::getpid()) + "_" + name + ".vtp");
}

// A small solution as writeSolutionVtp writes it (closed cube, 2 elements per face).
vtkSmartPointer<vtkPolyData> cubeSolution() {
  const PatchMesh mesh = testing::closedCube(0.5);
  std::vector<Rgb> b(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) b[e] = Rgb::all(0.5 + 0.1 * mesh.patch(e));
  vtkSmartPointer<vtkPolyData> data = makeSolutionPolyData(mesh, b, {}, ToneMap{0.7});
  auto scene = vtkSmartPointer<vtkStringArray>::New();
  scene->SetName("scene");
  scene->InsertNextValue("cube.obj");
  data->GetFieldData()->AddArray(scene);
  return data;
}

std::string written(vtkPolyData* data) {
  std::ostringstream out;
  writeSolutionVtp(out, data);
  return out.str();
}

// Replaces the first `from` (which must occur) by `to`.
std::string edited(std::string bytes, const std::string& from, const std::string& to) {
  const std::size_t at = bytes.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) bytes.replace(at, from.size(), to);
  return bytes;
}

int lineOf(const std::string& bytes, const std::string& text) {
  const std::size_t at = bytes.find(text);
  return 1 + static_cast<int>(std::count(bytes.begin(), bytes.begin() + at, '\n'));
}

// Writes `bytes` as a file and reads it with readSolutionVtp: the InputError it must throw.
InputError refusal(const std::string& name, const std::string& bytes) {
  const fs::path path = scratchFile(name);
  std::ofstream(path, std::ios::binary) << bytes;
  try {
    readSolutionVtp(path.string());
  } catch (const InputError& e) {
    fs::remove(path);
    EXPECT_EQ(e.file(), path.string()) << e.what();
    return e;
  }
  fs::remove(path);
  ADD_FAILURE() << name << ": accepted";
  return InputError("accepted");
}

TEST(SolutionVtpLayout, TheWritersOwnFilePasses) {
  vtkSmartPointer<vtkPolyData> data = cubeSolution();
  const std::string bytes = written(data);
  EXPECT_NO_THROW(checkSolutionVtpLayout("cube.vtp", bytes));
  const fs::path path = scratchFile("layout_ok");
  std::ofstream(path, std::ios::binary) << bytes;
  vtkSmartPointer<vtkPolyData> back = readSolutionVtp(path.string());
  fs::remove(path);
  EXPECT_EQ(back->GetNumberOfCells(), data->GetNumberOfCells());
  EXPECT_EQ(back->GetNumberOfPoints(), data->GetNumberOfPoints());
  EXPECT_EQ(solutionSceneFile(back), "cube.obj");
}

// The SEGV the solution_vtp fuzzer found in VTK 9.1's reader, in the writer's binary format:
// the field array "scene" holds two strings and says NumberOfTuples="1".
TEST(SolutionVtpLayout, MoreStringsThanTuplesIsRefusedBeforeVtkReadsThem) {
  vtkSmartPointer<vtkPolyData> data = cubeSolution();
  vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("scene"))
      ->InsertNextValue("second.obj");
  const std::string two = written(data);
  const std::string element = "<Array type=\"String\" Name=\"scene\" NumberOfTuples=\"";
  const std::string bytes = edited(two, element + "2\"", element + "1\"");
  const InputError e = refusal("string_values", bytes);
  EXPECT_NE(std::string(e.what()).find("holds 2 NUL-terminated strings"), std::string::npos)
      << e.what();
  EXPECT_EQ(e.line(), lineOf(bytes, "<Array")) << e.what();
  // And fewer strings than tuples.
  const InputError fewer = refusal("string_fewer", edited(two, element + "2\"", element + "3\""));
  EXPECT_NE(std::string(fewer.what()).find("'scene'"), std::string::npos) << fewer.what();
}

// Each change makes a file the writer never writes; VTK would read most of them, some into
// arrays of the wrong size. Every one is refused, naming the element's line.
TEST(SolutionVtpLayout, XmlTheWriterNeverWritesIsRefused) {
  const std::string bytes = written(cubeSolution());
  struct Case {
    const char* name;
    std::string from, to;
    const char* expected;  // in the message
  };
  const Case cases[] = {
      {"declaration", "<VTKFile", "<?xml version=\"1.0\"?>\n<VTKFile", "declaration"},
      {"comment", "<PolyData>", "<PolyData>\n<!-- x -->", "comment"},
      {"ascii", "format=\"appended\"", "format=\"ascii\"", "format"},
      {"lz4", "vtkZLibDataCompressor", "vtkLZ4DataCompressor", "compressor"},
      {"header64", "header_type=\"UInt32\"", "header_type=\"UInt64\"", "header_type"},
      {"base64", "encoding=\"raw\"", "encoding=\"base64\"", "encoding"},
      {"big_endian", "LittleEndian", "BigEndian", "byte_order"},
      {"float32", "type=\"Float64\" Name=\"B\"", "type=\"Float32\" Name=\"B\"", "bytes, expected"},
      {"components", "Name=\"B\" NumberOfComponents=\"3\"", "Name=\"B\" NumberOfComponents=\"4\"",
       "bytes, expected"},
      {"more_polys", "NumberOfPolys=\"", "NumberOfPolys=\"1", "bytes, expected"},
      {"more_points", "NumberOfPoints=\"", "NumberOfPoints=\"2", "bytes, expected"},
      {"bit_type", "type=\"Int32\" Name=\"patch\"", "type=\"Bit\" Name=\"patch\"", "unknown type"},
      {"cell_string", "<DataArray type=\"Int32\" Name=\"level\"",
       "<Array type=\"String\" Name=\"level\"", "outside field data"},
      {"attribute", "Name=\"area\"", "Name=\"area\" ComponentName0=\"x\"", "unexpected attribute"},
      {"entity", "Name=\"area\"", "Name=\"a&amp;rea\"", "character"},
      {"verts", "NumberOfVerts=\"0\"", "NumberOfVerts=\"1\"", "triangles only"},
      {"duplicate", "Name=\"material\"", "Name=\"patch\"", "twice"},
      {"huge_tuples", "Name=\"exposure\" NumberOfTuples=\"1\"",
       "Name=\"exposure\" NumberOfTuples=\"99999999999999999999\"", "too large"},
      {"negative", "Name=\"exposure\" NumberOfTuples=\"1\"",
       "Name=\"exposure\" NumberOfTuples=\"-1\"", "whole number"},
      {"children", "<Points>", "<Points>\n<Points>", "DataArray"},
      {"moved_offset", "offset=\"0\"", "offset=\"1\"", "offset 1, expected 0"},
  };
  for (const Case& c : cases) {
    const std::string bad = edited(bytes, c.from, c.to);
    const InputError e = refusal(c.name, bad);
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
        << c.name << ": " << e.what();
    EXPECT_GT(e.line(), 0) << c.name << ": " << e.what();
  }
}

// Damage to the appended data: every block must inflate to exactly the size its header gives,
// and the arrays must fill the data end to end.
TEST(SolutionVtpLayout, DamagedBlocksAreRefused) {
  const std::string bytes = written(cubeSolution());
  const std::size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1;
  const std::size_t tail = bytes.rfind("\n  </AppendedData>");
  ASSERT_LT(data, tail);

  EXPECT_NE(std::string(refusal("truncated", bytes.substr(0, bytes.size() - 40)).what())
                .find("does not end"),
            std::string::npos);
  std::string extra = bytes;
  extra.insert(tail, "xx");
  EXPECT_NE(std::string(refusal("extra", extra).what()).find("2 bytes of appended data after"),
            std::string::npos);
  // The first array (exposure): one block of 8 bytes; its header is 4 UInt32 words.
  std::string flipped = bytes;
  flipped[data + 16 + 2] ^= 0x55;
  EXPECT_NE(std::string(refusal("flipped", flipped).what()).find("does not inflate"),
            std::string::npos);
  std::string longer = bytes;
  longer[data + 8] = 9;  // the last (only) block's size: 9 bytes, not one Float64
  EXPECT_NE(std::string(refusal("longer", longer).what()).find("9 bytes, expected 1 values"),
            std::string::npos);
  std::string blocks = bytes;
  blocks[data + 3] = 0x7f;  // 2^30 blocks in a small file
  EXPECT_NE(std::string(refusal("blocks", blocks).what()).find("more compressed blocks"),
            std::string::npos);
}

// A quad and a two-point cell hold 6 point ids like two triangles: only the offsets tell them
// apart. VTK's writer cannot write a two-point polygon, so the last array of the file (the
// polygons' offsets) is replaced by 4, 6, 9, 12, ... compressed as the writer compresses.
TEST(SolutionVtpLayout, CellsOtherThanTrianglesAreRefused) {
  vtkSmartPointer<vtkPolyData> data = cubeSolution();
  const std::string bytes = written(data);
  const std::size_t data0 = bytes.find('_', bytes.find("<AppendedData")) + 1;
  const std::size_t tail = bytes.rfind("\n  </AppendedData>");
  const std::size_t key = bytes.rfind("offset=\"", data0) + 8;
  const std::size_t lastArray = data0 + std::stoul(bytes.substr(key, bytes.find('"', key) - key));
  const vtkIdType cells = data->GetNumberOfCells();
  std::vector<std::int64_t> offsets(cells);
  for (vtkIdType c = 0; c < cells; ++c) offsets[c] = 3 * (c + 1);
  offsets[0] = 4;  // a quad, then a two-point cell: the connectivity is unchanged
  const uLong raw = static_cast<uLong>(offsets.size() * sizeof(std::int64_t));
  std::vector<unsigned char> packed(compressBound(raw));
  uLongf packedSize = packed.size();
  ASSERT_EQ(compress2(packed.data(), &packedSize, reinterpret_cast<const Bytef*>(offsets.data()),
                      raw, Z_DEFAULT_COMPRESSION),
            Z_OK);
  const std::uint32_t header[4] = {1, 32768, static_cast<std::uint32_t>(raw),
                                   static_cast<std::uint32_t>(packedSize)};
  ASSERT_LT(raw, 32768u);
  std::string bad = bytes.substr(0, lastArray);
  bad.append(reinterpret_cast<const char*>(header), sizeof header);  // little-endian host
  bad.append(reinterpret_cast<const char*>(packed.data()), packedSize);
  bad.append(bytes.substr(tail));
  const InputError e = refusal("quad", bad);
  EXPECT_NE(std::string(e.what()).find("offset 0 is not 3"), std::string::npos) << e.what();
  EXPECT_EQ(e.line(), lineOf(bad, "<Polys>") + 2) << e.what();
  // The same bytes with 3 restored pass: the replacement itself is what the writer writes.
  offsets[0] = 3;
  packedSize = packed.size();
  ASSERT_EQ(compress2(packed.data(), &packedSize, reinterpret_cast<const Bytef*>(offsets.data()),
                      raw, Z_DEFAULT_COMPRESSION),
            Z_OK);
  std::string good = bytes.substr(0, lastArray);
  const std::uint32_t goodHeader[4] = {1, 32768, static_cast<std::uint32_t>(raw),
                                       static_cast<std::uint32_t>(packedSize)};
  good.append(reinterpret_cast<const char*>(goodHeader), sizeof goodHeader);
  good.append(reinterpret_cast<const char*>(packed.data()), packedSize);
  good.append(bytes.substr(tail));
  EXPECT_NO_THROW(checkSolutionVtpLayout("good.vtp", good));
}

}  // namespace
}  // namespace rad
