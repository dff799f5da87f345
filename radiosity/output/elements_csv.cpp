#include "radiosity/output/elements_csv.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <ios>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace rad {
namespace {

constexpr size_t kBlockBytes = 1 << 16;

// The comma-separated fields of one line, as views into it.
std::vector<std::string_view> splitCsv(std::string_view line) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  for (size_t comma; (comma = line.find(',', start)) != std::string_view::npos; start = comma + 1)
    fields.push_back(line.substr(start, comma - start));
  fields.push_back(line.substr(start));
  return fields;
}

// A finite number in decimal notation, read with std::from_chars (no locale to consult per number:
// several times faster than strtod on large solutions). Leading blanks and a '+' are allowed, as
// strtod allows them; hexadecimal is refused. A value beyond double's range is read by strtod, so
// an underflow still reads as (nearly) 0 and an overflow is refused as infinite.
double parseNumber(std::string_view text, const std::string& file, int line) {
  std::string_view digits = text;
  while (!digits.empty() && std::isspace(static_cast<unsigned char>(digits.front())))
    digits.remove_prefix(1);
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
  double v = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  const bool whole = !digits.empty() && end == digits.data() + digits.size();
  if (whole && error == std::errc::result_out_of_range)
    v = std::strtod(std::string(digits).c_str(), nullptr);
  if (!whole || (error != std::errc() && error != std::errc::result_out_of_range) ||
      !std::isfinite(v))
    throw InputError(file, line, "not a finite number: '" + std::string(text) + "'");
  return v;
}

int parseIndex(std::string_view text, const char* what, const std::string& file, int line) {
  const double v = parseNumber(text, file, line);
  if (!(v >= 0 && v <= std::numeric_limits<int>::max() && v == std::floor(v)))
    throw InputError(
        file, line,
        std::string(what) + " must be a non-negative integer, not '" + std::string(text) + "'");
  return static_cast<int>(v);
}

// A 64-bit mask in hexadecimal, 1 to 16 digits without a prefix, as writeElementsCsv writes it.
uint64_t parseMask(std::string_view text, const std::string& file, int line) {
  uint64_t mask = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), mask, 16);
  if (text.empty() || text.size() > 16 || error != std::errc() || end != text.data() + text.size())
    throw InputError(file, line,
                     std::string(kBuriedCellsColumn) +
                         " must be a 64-bit mask in hexadecimal (1 to 16 digits), not '" +
                         std::string(text) + "'");
  return mask;
}

}  // namespace

void writeElementsCsv(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity,
                      const std::vector<uint64_t>* buriedCells,
                      const std::vector<Rgb>* directIrradiance) {
  const int count = mesh.elementCount();
  RAD_CHECK_EQ(radiosity.size(), count);
  if (buriedCells) RAD_CHECK_EQ(buriedCells->size(), count);
  if (directIrradiance) RAD_CHECK_EQ(directIrradiance->size(), count);
  // std::to_chars writes the shortest text that reads back as the same double, with no locale or
  // stream state to consult per number: writing the outputs was a large part of a relight's time.
  // Rows are formatted into a buffer and written in blocks.
  std::string block;
  block.reserve(kBlockBytes + 512);
  char number[32];
  const auto field = [&](auto value, char after) {
    const auto [end, error] = std::to_chars(number, number + sizeof number, value);
    RAD_CHECK(error == std::errc());
    block.append(number, end);
    block.push_back(after);
  };
  block += kElementsCsvHeader;
  if (directIrradiance) block += std::string(",") + kDirectIrradianceColumns;
  if (buriedCells) block += std::string(",") + kBuriedCellsColumn;
  block += '\n';
  for (int e = 0; e < count; ++e) {
    const Eigen::Vector3d c = mesh.centroid(e);
    const Eigen::Vector3d n = mesh.normal(e);
    const Rgb& b = radiosity[e];
    const Rgb l = b / M_PI;
    field(e, ',');
    field(mesh.patch(e), ',');
    field(mesh.material(e), ',');
    field(mesh.area(e), ',');
    for (const double v : {c.x(), c.y(), c.z(), n.x(), n.y(), n.z(), b.r, b.g, b.b, l.r, l.g})
      field(v, ',');
    field(l.b, directIrradiance || buriedCells ? ',' : '\n');
    if (directIrradiance) {
      const Rgb& d = (*directIrradiance)[e];
      field(d.r, ',');
      field(d.g, ',');
      field(d.b, buriedCells ? ',' : '\n');
    }
    if (buriedCells) {
      const auto [end, error] =
          std::to_chars(number, number + sizeof number, (*buriedCells)[e], 16);
      RAD_CHECK(error == std::errc());
      block.append(number, end);
      block.push_back('\n');
    }
    if (block.size() >= kBlockBytes) {
      out.write(block.data(), static_cast<std::streamsize>(block.size()));
      block.clear();
    }
  }
  out.write(block.data(), static_cast<std::streamsize>(block.size()));
}

ElementsCsv readElementsCsv(std::istream& in, const std::string& source) {
  // The whole file at once, split into lines here: per-line getline and per-field strings were
  // most of the time a large solution took to read.
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::string_view rest = text;
  // A file saved with CRLF line ends reads the same.
  auto next = [&](std::string_view& line) {
    if (rest.empty()) return false;
    const size_t end = rest.find('\n');
    line = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return true;
  };
  std::string_view line;
  ElementsCsv csv;
  // The header: kElementsCsvHeader, then optionally the Ed columns, then optionally buried_cells.
  const std::string_view base = kElementsCsvHeader;
  const std::string ed = std::string(",") + kDirectIrradianceColumns;
  const std::string buried = std::string(",") + kBuriedCellsColumn;
  std::string_view header;
  const auto take = [&header](std::string_view part) {
    if (header.substr(0, part.size()) != part) return false;
    header.remove_prefix(part.size());
    return true;
  };
  bool known = next(header) && take(base);
  if (known) {
    csv.hasDirectIrradiance = take(ed);
    csv.hasBuriedCells = take(buried);
    known = header.empty();
  }
  if (!known)
    throw InputError(source, 1,
                     std::string("not an elements CSV (header missing; expected '") +
                         kElementsCsvHeader + "', optionally followed by '" + ed + "' and by '" +
                         buried + "')");
  constexpr int firstEd = 16;  // the first Ed column, after L_b
  const size_t fields = 16 + (csv.hasDirectIrradiance ? 3 : 0) + (csv.hasBuriedCells ? 1 : 0);
  std::vector<ElementsCsvRow>& rows = csv.rows;
  rows.reserve(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')));
  for (int lineNumber = 2; next(line); ++lineNumber) {
    if (line.empty()) continue;
    const std::vector<std::string_view> f = splitCsv(line);
    if (f.size() != fields)
      throw InputError(source, lineNumber,
                       "expected " + std::to_string(fields) + " comma-separated fields, found " +
                           std::to_string(f.size()));
    auto number = [&](int k) { return parseNumber(f[k], source, lineNumber); };
    ElementsCsvRow row;
    row.line = lineNumber;
    row.element = parseIndex(f[0], "element", source, lineNumber);
    row.patch = parseIndex(f[1], "patch", source, lineNumber);
    row.material = parseIndex(f[2], "material", source, lineNumber);
    row.area = number(3);
    row.centroid = Eigen::Vector3d(number(4), number(5), number(6));
    row.normal = Eigen::Vector3d(number(7), number(8), number(9));
    row.radiosity = Rgb(number(10), number(11), number(12));
    row.radiance = Rgb(number(13), number(14), number(15));
    if (csv.hasDirectIrradiance) {
      row.directIrradiance = Rgb(number(firstEd), number(firstEd + 1), number(firstEd + 2));
      for (int c = 0; c < 3; ++c)
        if (row.directIrradiance[c] < 0)
          throw InputError(source, lineNumber,
                           std::string("Ed_") + "rgb"[c] + " (direct irradiance) must be " +
                               "non-negative, not '" + std::string(f[firstEd + c]) + "'");
    }
    if (csv.hasBuriedCells) row.buriedCells = parseMask(f.back(), source, lineNumber);
    rows.push_back(row);
  }
  return csv;
}

ElementsCsv readElementsCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the elements CSV");
  return readElementsCsv(in, path);
}

}  // namespace rad
