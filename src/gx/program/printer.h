// Writes a ProgramFile as C that a libogc project compiles and that parse_program reads back to
// the same calls: floats with 9 significant digits (every float round-trips exactly), names as
// gx.h spells them, comments as // lines.
#pragma once

#include <string>

#include "gx/program/program_file.h"

namespace lt::gx {

std::string print_arg(const Arg& arg);
std::string print_program(const ProgramFile& program);

}  // namespace lt::gx
