// Accessors (glTF 2.0 §3.6): typed views into buffer views, read with every bound checked
// before a byte is touched, so a bad offset, count or stride is an InputError naming
// "/accessors/N", never a read beyond a buffer.
#pragma once

#include <string>
#include <vector>

#include "load/gltf/gltf_document.h"

namespace lt::gltf {

struct AccessorValues {
  int components = 0;          // 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4
  std::vector<double> values;  // count * components, element after element
  std::size_t count() const { return components ? values.size() / components : 0; }
};

// Reads accessor `index` as doubles. Normalised integers map to [0, 1] (unsigned) or [-1, 1]
// (signed) as §3.11 specifies; other integers keep their value. `use` says what the accessor is
// for ("POSITION", "indices") in messages; `types` lists the element types allowed for it
// (e.g. {3} for POSITION, {3, 4} for COLOR_0). Throws InputError for a bad index, a type not
// allowed, a sparse accessor, a buffer view or buffer it overruns, or a stride below the element.
AccessorValues read_accessor(const Document& doc, int index, const std::string& use,
                             std::initializer_list<int> types);

// "/accessors/N".
std::string accessor_pointer(int index);

}  // namespace lt::gltf
