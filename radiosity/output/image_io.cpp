#include "radiosity/output/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "radiosity/core/atomic_file.h"
#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace {

// stb's PNG encoder deflates through zlib (level 3), not its own compressor: Sponza's 1573×1583
// lightmap page in 0.15 s and 704 kB, against stb's own 0.38 s and 824 kB.
unsigned char* zlibCompress(unsigned char* data, int size, int* compressedSize, int /*quality*/) {
  uLongf capacity = compressBound(static_cast<uLong>(size));
  auto* out = static_cast<unsigned char*>(std::malloc(capacity));  // stb frees it with free()
  if (out && compress2(out, &capacity, data, static_cast<uLong>(size), 3) == Z_OK) {
    *compressedSize = static_cast<int>(capacity);
    return out;
  }
  std::free(out);
  return nullptr;  // stb reports the encoding as failed
}

}  // namespace

// stb's PNG encoder, compiled privately into this file only.
#define STBIW_ZLIB_COMPRESS zlibCompress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace rad {

void writeExr(const std::string& path, const ImageRgb& image) { writeExr(path, image, {}); }

void writeExr(const std::string& path, const ImageRgb& image,
              const std::vector<ExrChannel>& extra) {
  AtomicPath file(path);
  writeExr(file, image, extra);
  file.commit();
}

void writeExr(const AtomicPath& file, const ImageRgb& image, const std::vector<ExrChannel>& extra) {
  const int w = image.width, h = image.height;
  std::vector<float> channels[3];
  for (int c = 0; c < 3; ++c) {
    channels[c].resize(static_cast<size_t>(w) * h);
    for (size_t i = 0; i < channels[c].size(); ++i)
      channels[c][i] = static_cast<float>(image.pixels[i][c]);
  }
  for (const ExrChannel& channel : extra) {
    RAD_CHECK_EQ(channel.values.size(), static_cast<size_t>(w) * h);
    RAD_CHECK_MSG(
        channel.name != "R" && channel.name != "G" && channel.name != "B" && !channel.name.empty(),
        "writeExr: an extra channel needs a name of its own");
  }
  try {
    Imf::Header header(w, h);
    const char* names[3] = {"R", "G", "B"};
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(channels[c].data()),
                                        sizeof(float), sizeof(float) * w));
    }
    for (const ExrChannel& channel : extra) {
      header.channels().insert(channel.name, Imf::Channel(Imf::FLOAT));
      // OpenEXR's slices take a writable base pointer; it only reads from it here.
      char* base = reinterpret_cast<char*>(const_cast<float*>(channel.values.data()));
      frame.insert(channel.name, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * w));
    }
    // Its ZIP compression on as many cores as the command may use (OpenEXR's own thread pool,
    // sized to TBB's limit, which --threads sets, at most the cores): a page of 2.5 million texels
    // took 0.6 s on one.
    const int threads = static_cast<int>(std::clamp<size_t>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism), 1,
        static_cast<size_t>(tbb::info::default_concurrency())));
    {
      static std::mutex poolResize;
      const std::lock_guard<std::mutex> lock(poolResize);
      if (Imf::globalThreadCount() != threads) Imf::setGlobalThreadCount(threads);
    }
    // ZIP at zlib's fastest level: Sponza's lightmap page (1573×1583, four float channels) in
    // 0.74–0.80 s on one core against 0.93–1.04 s at levels 4–6, for a file 4% larger.
    header.zipCompressionLevel() = 1;
    Imf::OutputFile out(file.tempPath().c_str(), header, threads);
    out.setFrameBuffer(frame);
    out.writePixels(h);
  } catch (const std::exception& e) {
    throw RuntimeFailure("cannot write " + file.path() + ": " + e.what());
  }
}

std::vector<float> readExrChannel(const std::string& path, const std::string& name) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "cannot open EXR file");
  try {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    if (w <= 0 || h <= 0) throw InputError(path, 0, "EXR file has an empty data window");
    if (!in.header().channels().findChannel(name))
      throw InputError(path, 0, "EXR file has no '" + name + "' channel");
    std::vector<float> values(static_cast<size_t>(w) * h);
    char* base = reinterpret_cast<char*>(values.data()) -
                 (static_cast<ptrdiff_t>(window.min.x) + static_cast<ptrdiff_t>(window.min.y) * w) *
                     sizeof(float);
    Imf::FrameBuffer frame;
    frame.insert(name, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * w));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return values;
  } catch (const InputError&) {
    throw;
  } catch (const CheckFailure&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, 0, std::string("not a readable EXR file: ") + e.what());
  }
}

ImageRgb readExr(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "cannot open EXR file");
  try {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    if (w <= 0 || h <= 0) throw InputError(path, 0, "EXR file has an empty data window");
    const char* names[3] = {"R", "G", "B"};
    for (const char* name : names)
      if (!in.header().channels().findChannel(name))
        throw InputError(path, 0, std::string("EXR file has no '") + name + "' channel");
    std::vector<float> channels[3];
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
      channels[c].resize(static_cast<size_t>(w) * h);
      char* base =
          reinterpret_cast<char*>(channels[c].data()) -
          (static_cast<ptrdiff_t>(window.min.x) + static_cast<ptrdiff_t>(window.min.y) * w) *
              sizeof(float);
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * w));
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    ImageRgb image(w, h);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      image.pixels[i] = {channels[0][i], channels[1][i], channels[2][i]};
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const CheckFailure&) {
    throw;  // a bug here, not a bad file
  } catch (const std::exception& e) {
    throw InputError(path, 0, std::string("not a readable EXR file: ") + e.what());
  }
}

std::vector<std::uint8_t> encodePng(const ImageRgb& radiance, const ToneMap& toneMap) {
  std::vector<std::uint8_t> rgb(static_cast<size_t>(radiance.width) * radiance.height * 3);
  // The tone map (a pow per channel) in parallel: most of a large page's encoding time.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, radiance.pixels.size(), 16384),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) {
                        const auto c = toneMap.toSrgb8(radiance.pixels[i]);
                        rgb[3 * i + 0] = c[0];
                        rgb[3 * i + 1] = c[1];
                        rgb[3 * i + 2] = c[2];
                      }
                    });
  std::vector<std::uint8_t> png;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (!stbi_write_png_to_func(append, &png, radiance.width, radiance.height, 3, rgb.data(),
                              radiance.width * 3))
    throw RuntimeFailure("PNG encoding failed");
  return png;
}

void writePng(const std::string& path, const ImageRgb& radiance, const ToneMap& toneMap) {
  const std::vector<std::uint8_t> png = encodePng(radiance, toneMap);
  AtomicFile file(path, /*binary=*/true);
  file.stream().write(reinterpret_cast<const char*>(png.data()),
                      static_cast<std::streamsize>(png.size()));
  file.commit();
}

}  // namespace rad
