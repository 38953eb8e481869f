// Reads a GX program file (gx.md §1) into a ProgramFile: the C subset a porter writes for GX
// setup code. Syntax only; what the calls mean is the interpreter's (interpreter.h). Every error
// is an InputError naming `file:line:column` and what was expected, as a compiler would.
#pragma once

#include <filesystem>
#include <string>

#include "gx/program/program_file.h"

namespace lt::gx {

ProgramFile parse_program(const std::string& text, const std::string& file_for_errors);
// Reads and parses a file (InputError for a missing or unreadable one).
ProgramFile load_program(const std::filesystem::path& path);

}  // namespace lt::gx
