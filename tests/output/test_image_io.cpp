#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "radiosity/core/errors.h"
#include "radiosity/output/image_io.h"

namespace rad {
namespace {

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("radiosity_image_io_" + name);
}

TEST(ImageIo, ExrRoundTripsFloatValuesExactly) {
  ImageRgb image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = {x + 0.25 * y, 1e-6 * (x + 1), 1e5 + y};
  image.at(2, 1) = {17, 12, 4};  // an emitter's Ke must survive bit for bit
  const auto path = scratch("roundtrip.exr");
  writeExr(path.string(), image);
  const ImageRgb back = readExr(path.string());
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(back.pixels[i][c], static_cast<double>(static_cast<float>(image.pixels[i][c])));
  EXPECT_EQ(back.at(2, 1).r, 17.0);
  EXPECT_EQ(back.at(2, 1).g, 12.0);
  EXPECT_EQ(back.at(2, 1).b, 4.0);
  std::filesystem::remove(path);
}

TEST(ImageIo, ReadingAMissingOrBrokenExrNamesTheFile) {
  EXPECT_THROW(readExr(scratch("missing.exr").string()), InputError);
  const auto path = scratch("broken.exr");
  std::ofstream(path) << "not an exr";
  try {
    readExr(path.string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST(ImageIo, PngHasSignatureSizeAndNoTemporaryLeft) {
  ImageRgb image(4, 2);
  image.at(0, 0) = {1, 1, 1};
  const auto dir = scratch("png");
  std::filesystem::create_directories(dir);
  writePng((dir / "a.png").string(), image, ToneMap{1.0});
  std::ifstream in(dir / "a.png", std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes[1], 'P');
  EXPECT_EQ(bytes[2], 'N');
  EXPECT_EQ(bytes[3], 'G');
  // IHDR width and height, big-endian at bytes 16..23.
  EXPECT_EQ(bytes[19], 4);
  EXPECT_EQ(bytes[23], 2);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) ++files, (void)entry;
  EXPECT_EQ(files, 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rad
