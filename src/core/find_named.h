// Looking up a named entry of a fixed list (paths, profiles) by what the user typed: the entry,
// or one InputError naming the option, the value and every valid name, so a typo says what it
// could have been.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"

namespace lt {

// `T` has a `name` member; `option` is the command-line option ("--path"), `what` the kind of
// thing ("path", "gx profile").
template <class T>
const T& find_named(const std::vector<T>& items, const std::string& name, const std::string& option,
                    const std::string& what) {
  std::string names;
  for (const T& item : items) {
    if (item.name == name) return item;
    names += (names.empty() ? "" : ", ") + item.name;
  }
  throw InputError(option, name, "unknown " + what + " (valid: " + names + ")");
}

}  // namespace lt
