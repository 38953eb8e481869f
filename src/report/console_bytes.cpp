#include "report/console_bytes.h"

#include <string>

namespace lt {

std::optional<ConsoleBytes> console_bytes(const budget::Report& report) {
  auto number = [&](const std::string& key) -> std::optional<std::size_t> {
    for (const budget::Detail& d : report.details)
      if (d.key == key && d.number) return static_cast<std::size_t>(*d.number);
    return std::nullopt;
  };
  if (!number("fifo_bytes")) return std::nullopt;
  ConsoleBytes c;
  for (const auto& [name, field] : ConsoleBytes::kFields) c.*field = number(name).value_or(0);
  return c;
}

}  // namespace lt
