// This process's own command line, as the kernel keeps it, without argv[0]: a child process of
// ltrender itself (a bench job, a regress worker) parses exactly what its parent parsed, so no
// option has to be written out a second time.
#pragma once

#include <string>
#include <vector>

namespace lt::cli {

std::vector<std::string> own_arguments();

}  // namespace lt::cli
