#include "regress/test_hook.h"

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <thread>

namespace lt {

void run_regress_test_hook(const std::string& case_id) {
  const char* hook = std::getenv(kRegressTestHookVariable);
  if (!hook) return;
  std::stringstream entries(hook);
  for (std::string entry; std::getline(entries, entry, ';');) {
    const size_t at = entry.find('@');
    if (at == std::string::npos || entry.substr(at + 1) != case_id) continue;
    const std::string action = entry.substr(0, at);
    if (action == "abort") std::abort();
    if (action == "hang") {
      for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
    }
  }
}

}  // namespace lt
