// The end of a program's output or log, for a one-line error message.
#pragma once

#include <filesystem>
#include <string>

namespace lt::judge {

// The last `lines` non-empty lines of `file`, without control characters, trimmed and joined with "
// | ", at most `max_chars` (the start cut, "..." in its place); empty if the file is missing or
// empty.
std::string log_tail(const std::filesystem::path& file, int lines = 3, std::size_t max_chars = 400);

}  // namespace lt::judge
