// Runs a program's libogc calls on the GX state, as libogc would write the registers: each call
// is checked against its prototype (argument count, the group of every GX_* name, ranges), and a
// call whose hardware behaviour the emulator does not model is an error, never a silent no-op.
#pragma once

#include <string>
#include <vector>

#include "gx/gx_state.h"
#include "gx/program/program_file.h"

namespace lt::gx {

// The GX state after running `blocks` in order on GX_Init's state (gx.md §1): e.g. a file's
// top-level statements, then one pass function. Variables (light and texture objects, matrices,
// arrays) live for the whole run, as a C program's would. Throws InputError naming
// `file:line:column` for an unknown call, a wrong argument count, a name of the wrong group, a
// value out of range or an unmodelled call.
GxState run_program(const std::string& file,
                    const std::vector<const std::vector<Statement>*>& blocks);

}  // namespace lt::gx
