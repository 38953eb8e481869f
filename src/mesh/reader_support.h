// What every mesh format's reader or check uses: whole-token number parsing, lines and tokens
// of a text file, and the error that names the file and line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace lt::meshio {

// "1 vertex", "3 vertices".
std::string plural(std::size_t n, const std::string& one, const std::string& many);

// Whole-token number parsing: "1.5x" is not a number (istream would read 1.5 and stop).
bool parse_double(std::string_view token, double& out);
bool parse_int(std::string_view token, long long& out);

// OpenMesh's text readers read numbers with `istream >> float`: NaN, Inf and anything beyond
// float range put the stream into a failed state, after which every later value is garbage.
bool fits_openmesh_float(double v);

std::vector<std::string_view> split_whitespace(std::string_view line);

// Text split into lines, without '\n' and a trailing '\r' (line n of the file is lines[n - 1]).
// The views point into `text`, which must outlive them.
std::vector<std::string_view> split_lines(const std::string& text);

std::string_view trim(std::string_view s);

// "'token'", for messages. Built by append: GCC 12 warns (-Wrestrict, a false positive, GCC bug
// 105329) on "'" + std::string(token) + "'" once inlined.
std::string quoted(std::string_view token);

// A UTF-8 byte-order mark, as Windows editors write one, is no part of a text format: assimp skips
// it (BaseImporter::ConvertToUTF8), while OpenMesh would read it into the first line (an OBJ's
// first vertex silently lost, every index after it shifted). Removes it from `text` when it starts
// `text` and returns the warning that says so ("" when there was none).
std::string skip_utf8_bom(std::string& text);
// UTF-16 text (a byte-order mark FE FF or FF FE first) is refused by name: read as bytes it has
// no vertex at all, and "mesh is empty" would not say why.
void refuse_utf16(const std::string& text, const std::string& file);

// Throws InputError for `file`, at `line` when it is not 0.
[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& what);

}  // namespace lt::meshio
