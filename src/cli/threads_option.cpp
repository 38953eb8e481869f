#include "cli/threads_option.h"

#include <string>

#include "core/cpu_affinity.h"
#include "core/parallel_rows.h"

namespace lt::cli {

void add_threads_option(CLI::App* command) {
  command
      ->add_option_function<unsigned>(
          "--threads", [](const unsigned& n) { worker_threads_setting() = n; },
          "Threads of the CPU paths' per-pixel shading (reference, half, gx); default: every "
          "core this process may use (" +
              std::to_string(usable_core_count()) + " here)")
      ->check(CLI::Range(1u, 1024u));
}

}  // namespace lt::cli
