#include "viewer/solution_vtp_layout.h"

#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <set>
#include <vector>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

// What vtkXMLPolyDataWriter writes after the last compressed block.
constexpr std::string_view kTail = "\n  </AppendedData>\n</VTKFile>\n";
// VTK's writer compresses in 32 KiB blocks; a larger block is not ours, and checking it would
// mean allocating whatever the file claims.
constexpr std::uint64_t kMaxBlockSize = std::uint64_t(1) << 20;
// Counts above this are refused before any arithmetic on them can overflow.
constexpr std::uint64_t kMaxCount = std::uint64_t(1) << 48;
constexpr std::uint64_t kMaxComponents = 9;

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  bool closing = false;      // </name>
  bool selfClosing = false;  // <name ... />
  int line = 0;
};

// The XML before the appended data, restricted to what VTK's writer emits: elements with
// double-quoted attributes of printable ASCII, whitespace between them; no declaration,
// comments, text, entities or CDATA (an XML parser could read those differently from us).
class XmlScanner {
 public:
  XmlScanner(const std::string& path, std::string_view text) : path_(path), text_(text) {}

  Element next() {
    skipSpace();
    Element e;
    e.line = line_;
    if (!take('<')) fail("expected an XML element");
    if (pos_ < text_.size() && (text_[pos_] == '?' || text_[pos_] == '!'))
      fail("an XML declaration, comment or DOCTYPE, which radiosity's solution.vtp never has");
    e.closing = take('/');
    e.name = word("an element name");
    for (;;) {
      const bool spaced = skipSpace();
      if (take('>')) break;
      if (take('/')) {
        if (e.closing || !take('>')) fail("malformed element <" + e.name + ">");
        e.selfClosing = true;
        break;
      }
      if (e.closing || !spaced) fail("malformed element <" + e.name + ">");
      const std::string key = word("an attribute name");
      if (!take('=') || !take('"'))
        fail("attribute " + key + " of <" + e.name + ">: expected =\"...\"");
      const std::size_t start = pos_;
      for (; pos_ < text_.size() && text_[pos_] != '"'; ++pos_) {
        const auto c = static_cast<unsigned char>(text_[pos_]);
        if (c < 0x20 || c > 0x7e || c == '<' || c == '&')
          fail("attribute " + key + " of <" + e.name +
               ">: a character VTK's writer does not write");
      }
      if (!take('"')) fail("attribute " + key + " of <" + e.name + "> is not terminated");
      const std::string value(text_.substr(start, pos_ - 1 - start));
      if (!e.attributes.emplace(key, value).second)
        fail("attribute " + key + " of <" + e.name + "> is given twice");
    }
    return e;
  }

  // After <AppendedData>: whitespace, then the '_' before the first byte of data.
  std::size_t appendedDataStart() {
    skipSpace();
    if (!take('_')) fail("expected '_' where the appended data start");
    return pos_;
  }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

 private:
  bool take(char c) {
    if (pos_ >= text_.size() || text_[pos_] != c) return false;
    ++pos_;
    return true;
  }
  bool skipSpace() {
    const std::size_t before = pos_;
    for (; pos_ < text_.size(); ++pos_) {
      const char c = text_[pos_];
      if (c == '\n')
        ++line_;
      else if (c != ' ' && c != '\t' && c != '\r')
        break;
    }
    return pos_ > before;
  }
  std::string word(const char* what) {
    const std::size_t start = pos_;
    auto isWordChar = [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    };
    while (pos_ < text_.size() && isWordChar(text_[pos_])) ++pos_;
    if (pos_ == start || (text_[start] >= '0' && text_[start] <= '9'))
      fail(std::string("expected ") + what);
    return std::string(text_.substr(start, pos_ - start));
  }

  const std::string& path_;
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

// What the values of one array must be, beyond their number.
enum class Content { any, strings, triangleOffsets };

// One appended array as the XML announces it.
struct ArraySpec {
  std::string what;  // "cell array 'B'", for messages
  int line = 0;
  std::uint64_t offset = 0;
  std::uint64_t values = 0;
  std::uint64_t wordSize = 1;  // bytes per value (1 for String: checked by counting strings)
  Content content = Content::any;
};

std::uint64_t wordSizeOf(const std::string& type) {
  static const std::map<std::string, std::uint64_t> sizes = {
      {"Int8", 1},   {"UInt8", 1}, {"Int16", 2},  {"UInt16", 2},  {"Int32", 4},
      {"UInt32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// Reads the element tree writeSolutionVtp produces and collects its arrays in document order.
class LayoutReader {
 public:
  LayoutReader(const std::string& path, std::string_view bytes) : path_(path), xml_(path, bytes) {}

  std::vector<ArraySpec> read(std::size_t& dataStart) {
    const Element file = open("VTKFile");
    only(file, {"type", "version", "byte_order", "header_type", "compressor"});
    expect(file, "type", "PolyData");
    expect(file, "version", "0.1");
    expect(file, "byte_order", "LittleEndian");
    expect(file, "header_type", "UInt32");
    expect(file, "compressor", "vtkZLibDataCompressor");
    only(open("PolyData"), {});
    only(open("FieldData"), {});
    arrays("FieldData", "field", 0);
    const Element piece = open("Piece");
    only(piece,
         {"NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"});
    const std::uint64_t points = count(piece, "NumberOfPoints");
    for (const char* other : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips"})
      if (count(piece, other) != 0) fail(piece, std::string(other) + " must be 0: triangles only");
    const std::uint64_t triangles = count(piece, "NumberOfPolys");
    only(open("PointData"), {});
    arrays("PointData", "point", points);
    only(open("CellData"), {});
    arrays("CellData", "cell", triangles);
    only(open("Points"), {});
    pointsArray(points);
    close("Points");
    for (const char* cells : {"Verts", "Lines", "Strips"}) {
      only(open(cells), {});
      cellArrays(cells, 0);
      close(cells);
    }
    only(open("Polys"), {});
    cellArrays("Polys", triangles);
    close("Polys");
    close("Piece");
    close("PolyData");
    const Element appended = open("AppendedData");
    only(appended, {"encoding"});
    expect(appended, "encoding", "raw");
    dataStart = xml_.appendedDataStart();
    return std::move(specs_);
  }

 private:
  [[noreturn]] void fail(const Element& e, const std::string& what) const {
    throw InputError(path_, e.line, what);
  }

  Element open(const std::string& name) {
    const Element e = xml_.next();
    if (e.closing || e.selfClosing || e.name != name)
      fail(e, "expected <" + name + ">, found <" + std::string(e.closing ? "/" : "") + e.name +
                  ">: not a solution.vtp written by radiosity");
    return e;
  }
  void close(const std::string& name) {
    const Element e = xml_.next();
    if (!e.closing || e.name != name)
      fail(e,
           "expected </" + name + ">, found <" + std::string(e.closing ? "/" : "") + e.name + ">");
  }
  void only(const Element& e, std::initializer_list<const char*> allowed) {
    for (const auto& [key, value] : e.attributes) {
      bool known = false;
      for (const char* a : allowed) known = known || key == a;
      if (!known) fail(e, "unexpected attribute " + key + " of <" + e.name + ">");
    }
  }
  std::string required(const Element& e, const std::string& key) {
    const auto it = e.attributes.find(key);
    if (it == e.attributes.end()) fail(e, "<" + e.name + "> lacks the attribute " + key);
    return it->second;
  }
  void expect(const Element& e, const std::string& key, const std::string& value) {
    const std::string got = required(e, key);
    if (got != value)
      fail(e, "<" + e.name + "> " + key + "=\"" + got + "\": expected \"" + value + "\"");
  }
  std::uint64_t number(const Element& e, const std::string& key, const std::string& text) {
    std::uint64_t n = 0;
    if (text.empty()) fail(e, key + " of <" + e.name + "> is empty");
    for (char c : text) {
      if (c < '0' || c > '9') fail(e, key + "=\"" + text + "\" is not a whole number");
      n = n * 10 + static_cast<std::uint64_t>(c - '0');
      if (n > kMaxCount) fail(e, key + "=\"" + text + "\" is too large");
    }
    return n;
  }
  std::uint64_t count(const Element& e, const std::string& key) {
    return number(e, key, required(e, key));
  }
  void optionalRange(const Element& e, const char* key) {
    const auto it = e.attributes.find(key);
    if (it == e.attributes.end() || it->second.empty()) return;
    char* end = nullptr;
    std::strtod(it->second.c_str(), &end);
    if (end != it->second.c_str() + it->second.size())
      fail(e, std::string(key) + "=\"" + it->second + "\" is not a number");
  }
  std::uint64_t components(const Element& e) {
    const auto it = e.attributes.find("NumberOfComponents");
    const std::uint64_t n = it == e.attributes.end() ? 1 : number(e, it->first, it->second);
    if (n < 1 || n > kMaxComponents)
      fail(e, "NumberOfComponents=\"" + std::to_string(n) + "\": expected 1 to " +
                  std::to_string(kMaxComponents));
    return n;
  }

  // An appended array element; returns its spec with `values` = tuples × components.
  ArraySpec array(const Element& e, const std::string& kind, std::uint64_t tuples) {
    if (e.closing || !e.selfClosing)
      fail(e, "expected an empty <DataArray .../> in " + kind + " data, found <" +
                  std::string(e.closing ? "/" : "") + e.name + ">");
    const bool field = kind == "field";
    if (field)
      only(e, {"type", "Name", "NumberOfComponents", "NumberOfTuples", "format", "RangeMin",
               "RangeMax", "offset"});
    else
      only(e, {"type", "Name", "NumberOfComponents", "format", "RangeMin", "RangeMax", "offset"});
    ArraySpec spec;
    spec.line = e.line;
    const std::string name = required(e, "Name"), type = required(e, "type");
    spec.what = kind + " array '" + name + "'";
    if (name.empty()) fail(e, "an array without a name");
    expect(e, "format", "appended");
    optionalRange(e, "RangeMin");
    optionalRange(e, "RangeMax");
    spec.offset = count(e, "offset");
    if (field) tuples = count(e, "NumberOfTuples");
    spec.values = tuples * components(e);  // both below 2^48 and 10
    // The writer's one String array is the scene's file name, a field array.
    if (type == "String") {
      if (!field || e.name != "Array") fail(e, spec.what + ": a String array outside field data");
      spec.content = Content::strings;
    } else {
      if (e.name != "DataArray") fail(e, spec.what + ": <" + e.name + "> of type " + type);
      spec.wordSize = wordSizeOf(type);
      if (spec.wordSize == 0) fail(e, spec.what + ": unknown type \"" + type + "\"");
    }
    return spec;
  }

  // Arrays of one section until its closing tag; names are unique within a section.
  void arrays(const std::string& section, const std::string& kind, std::uint64_t tuples) {
    std::set<std::string> names;
    for (Element e = xml_.next(); !(e.closing && e.name == section); e = xml_.next()) {
      specs_.push_back(array(e, kind, tuples));
      if (!names.insert(e.attributes.at("Name")).second)
        fail(e, specs_.back().what + " appears twice");
    }
  }

  void pointsArray(std::uint64_t points) {
    const Element e = xml_.next();
    ArraySpec spec = array(e, "point coordinates", points);
    const std::string type = e.attributes.at("type");
    if ((type != "Float32" && type != "Float64") || spec.values != 3 * points)
      fail(e, "point coordinates: expected 3 Float32 or Float64 components");
    specs_.push_back(spec);
  }

  // connectivity and offsets of one cell kind; `cells` triangles (offsets 3, 6, 9, ...).
  void cellArrays(const std::string& kind, std::uint64_t cells) {
    for (const char* name : {"connectivity", "offsets"}) {
      const Element e = xml_.next();
      const bool isOffsets = std::string(name) == "offsets";
      ArraySpec spec = array(e, kind, isOffsets ? cells : 3 * cells);
      const std::string type = e.attributes.at("type");
      if (e.attributes.at("Name") != name || (type != "Int32" && type != "Int64") ||
          spec.values != (isOffsets ? cells : 3 * cells))
        fail(e, kind + ": expected the Int32 or Int64 array '" + name + "' with one component");
      if (isOffsets) spec.content = Content::triangleOffsets;
      specs_.push_back(spec);
    }
  }

  const std::string& path_;
  XmlScanner xml_;
  std::vector<ArraySpec> specs_;
};

std::uint64_t littleEndian(const unsigned char* p, std::uint64_t bytes) {
  std::uint64_t v = 0;
  for (std::uint64_t i = bytes; i-- > 0;) v = (v << 8) | p[i];
  return v;
}

// Inflates one zlib block into exactly `size` bytes, consuming all of its input.
bool inflateExactly(const unsigned char* in, std::uint64_t inSize, unsigned char* out,
                    std::uint64_t size) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) throw RuntimeFailure("zlib: inflateInit failed");
  z.next_in = const_cast<unsigned char*>(in);
  z.avail_in = static_cast<uInt>(inSize);  // a UInt32 header word
  z.next_out = out;
  z.avail_out = static_cast<uInt>(size);  // at most kMaxBlockSize
  const int result = inflate(&z, Z_FINISH);
  const bool ok = result == Z_STREAM_END && z.avail_in == 0 && z.avail_out == 0;
  inflateEnd(&z);
  return ok;
}

// Follows the values of one array, block by block, for the checks of its Content.
class ContentCheck {
 public:
  explicit ContentCheck(const ArraySpec& spec) : spec_(spec) {}

  void feed(const unsigned char* data, std::uint64_t size) {
    for (std::uint64_t i = 0; i < size; ++i) {
      if (spec_.content == Content::strings) {
        strings_ += data[i] == 0;
        last_ = data[i];
      } else if (spec_.content == Content::triangleOffsets) {
        word_[have_++] = data[i];
        if (have_ < spec_.wordSize) continue;
        have_ = 0;
        const std::uint64_t expected = 3 * (++index_);
        if (badIndex_ == 0 && littleEndian(word_, spec_.wordSize) != expected) badIndex_ = index_;
      }
    }
  }

  // The failure, or "" when the values are as the layout requires.
  std::string problem(std::uint64_t bytes) const {
    if (spec_.content == Content::strings &&
        (strings_ != spec_.values || (bytes > 0 && last_ != 0)))
      return spec_.what + " holds " + std::to_string(strings_) +
             " NUL-terminated strings, its NumberOfTuples × NumberOfComponents is " +
             std::to_string(spec_.values);
    if (spec_.content == Content::triangleOffsets && badIndex_ != 0)
      return spec_.what + ": offset " + std::to_string(badIndex_ - 1) + " is not " +
             std::to_string(3 * badIndex_) + " (triangles only)";
    return "";
  }

 private:
  const ArraySpec& spec_;
  std::uint64_t strings_ = 0;
  unsigned char last_ = 0;
  unsigned char word_[8] = {};
  std::uint64_t have_ = 0, index_ = 0, badIndex_ = 0;
};

// Walks one array's compression header and blocks at `cursor` in the appended data, inflating
// each; returns the offset just past the array.
std::uint64_t checkBlocks(const std::string& path, const ArraySpec& spec, std::string_view data,
                          std::uint64_t cursor) {
  auto fail = [&](const std::string& what) {
    throw InputError(path, spec.line, spec.what + ": " + what);
  };
  if (spec.offset != cursor)
    fail("offset " + std::to_string(spec.offset) + ", expected " + std::to_string(cursor) +
         " (where the previous array ends)");
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const std::uint64_t size = data.size();
  if (size - cursor < 12) fail("the compression header runs past the end of the data");
  const std::uint64_t blocks = littleEndian(bytes + cursor, 4);
  const std::uint64_t blockSize = littleEndian(bytes + cursor + 4, 4);
  const std::uint64_t lastSize = littleEndian(bytes + cursor + 8, 4);
  cursor += 12;
  if (blocks > (size - cursor) / 4) fail("more compressed blocks than the file holds");
  if (blocks > 0 && (blockSize == 0 || blockSize > kMaxBlockSize || lastSize >= blockSize))
    fail("block size " + std::to_string(blockSize) + ", last block " + std::to_string(lastSize) +
         ": not what VTK's writer writes");
  const std::uint64_t total =
      blocks == 0 ? 0 : (blocks - (lastSize ? 1 : 0)) * blockSize + lastSize;
  if (spec.content != Content::strings && total != spec.values * spec.wordSize)
    fail("holds " + std::to_string(total) + " bytes, expected " + std::to_string(spec.values) +
         " values of " + std::to_string(spec.wordSize) + " bytes");
  const unsigned char* compressedSizes = bytes + cursor;
  cursor += 4 * blocks;
  std::vector<unsigned char> block(blocks > 0 ? blockSize : 0);
  ContentCheck content(spec);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressed = littleEndian(compressedSizes + 4 * b, 4);
    const std::uint64_t inflated = (b + 1 == blocks && lastSize) ? lastSize : blockSize;
    if (compressed > size - cursor)
      fail("block " + std::to_string(b) + " runs past the end of the data");
    if (!inflateExactly(bytes + cursor, compressed, block.data(), inflated))
      fail("block " + std::to_string(b) + " does not inflate to its " + std::to_string(inflated) +
           " bytes");
    content.feed(block.data(), inflated);
    cursor += compressed;
  }
  const std::string problem = content.problem(total);
  if (!problem.empty()) throw InputError(path, spec.line, problem);
  return cursor;
}

}  // namespace

void checkSolutionVtpLayout(const std::string& path, std::string_view bytes) {
  std::size_t dataStart = 0;
  const std::vector<ArraySpec> arrays = LayoutReader(path, bytes).read(dataStart);
  if (bytes.size() < dataStart + kTail.size() || bytes.substr(bytes.size() - kTail.size()) != kTail)
    throw InputError(path, 0, "does not end as VTK's writer ends a file (</AppendedData>)");
  const std::string_view data = bytes.substr(dataStart, bytes.size() - kTail.size() - dataStart);
  std::uint64_t cursor = 0;
  for (const ArraySpec& spec : arrays) cursor = checkBlocks(path, spec, data, cursor);
  if (cursor != data.size())
    throw InputError(
        path, 0,
        std::to_string(data.size() - cursor) + " bytes of appended data after the last array");
}

}  // namespace rad
