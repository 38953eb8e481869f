#include "load/gltf/gltf_accessor.h"

#include <algorithm>
#include <cstring>

namespace lt::gltf {

namespace {

std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
  }
  return 0;  // glTF 2.0 has no other component type (§3.6.2.2; 5124 INT is not allowed)
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
  }
  return 0;  // matrices: no attribute the importer reads is a matrix
}

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // glTF data is little-endian, like every machine we run on
  return v;
}

// §3.11 ("Animations", the normalisation table it shares with attributes): c / (2^n - 1) for
// unsigned, max(c / (2^(n-1) - 1), -1) for signed.
double component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = load<std::int8_t>(p);
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = load<std::uint8_t>(p);
      return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = load<std::int16_t>(p);
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = load<std::uint16_t>(p);
      return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      const double c = load<std::uint32_t>(p);
      return normalized ? c / 4294967295.0 : c;
    }
    default:
      return load<float>(p);
  }
}

}  // namespace

std::string accessor_pointer(int index) {
  return "/accessors/" + std::to_string(index);
}

AccessorValues read_accessor(const Document& doc, int index, const std::string& use,
                             std::initializer_list<int> types) {
  const tinygltf::Model& m = doc.model;
  const std::string ptr = accessor_pointer(index);
  if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size()) {
    doc.fail(ptr, use + " names accessor " + std::to_string(index) + ", the file has " +
                      std::to_string(m.accessors.size()));
  }
  const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(index)];
  AccessorValues out;
  out.components = component_count(a.type);
  if (std::find(types.begin(), types.end(), out.components) == types.end()) {
    doc.fail(ptr, use + " cannot be of this element type (" + std::to_string(out.components) +
                      " components)");
  }
  const std::size_t csize = component_size(a.componentType);
  if (csize == 0)
    doc.fail(ptr + "/componentType", "unknown component type " + std::to_string(a.componentType));
  if (a.sparse.isSparse) doc.fail(ptr + "/sparse", "sparse accessors are not read");
  const std::size_t element = csize * static_cast<std::size_t>(out.components);
  if (a.count > (std::size_t{1} << 31))
    doc.fail(ptr + "/count", "count " + std::to_string(a.count) + " is beyond any scene");
  out.values.assign(a.count * static_cast<std::size_t>(out.components), 0.0);
  // §3.6.2.1: an accessor without a buffer view is all zeros.
  if (a.bufferView < 0) return out;
  if (static_cast<std::size_t>(a.bufferView) >= m.bufferViews.size()) {
    doc.fail(ptr + "/bufferView", "names buffer view " + std::to_string(a.bufferView) +
                                      ", the file has " + std::to_string(m.bufferViews.size()));
  }
  const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::string view_ptr = "/bufferViews/" + std::to_string(a.bufferView);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m.buffers.size()) {
    doc.fail(view_ptr + "/buffer", "names buffer " + std::to_string(view.buffer) +
                                       ", the file has " + std::to_string(m.buffers.size()));
  }
  const std::vector<unsigned char>& buffer = m.buffers[static_cast<std::size_t>(view.buffer)].data;
  // §3.6.1: the view lies inside its buffer.
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
    doc.fail(view_ptr, "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                           std::to_string(view.byteLength) + " is beyond buffer " +
                           std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) +
                           " bytes)");
  }
  const std::size_t stride = view.byteStride ? view.byteStride : element;
  if (stride < element) {
    doc.fail(view_ptr + "/byteStride", "stride " + std::to_string(stride) +
                                           " is smaller than the element (" +
                                           std::to_string(element) + " bytes) of " + ptr);
  }
  // §3.6.2.4: offset + stride * (count - 1) + element <= the view's length.
  if (a.count > 0) {
    const std::size_t last_end = a.byteOffset + stride * (a.count - 1) + element;
    if (a.byteOffset > view.byteLength || last_end > view.byteLength) {
      doc.fail(ptr, "byteOffset " + std::to_string(a.byteOffset) + " + " + std::to_string(a.count) +
                        " elements of stride " + std::to_string(stride) + " need " +
                        std::to_string(last_end) + " bytes, buffer view " +
                        std::to_string(a.bufferView) + " has " + std::to_string(view.byteLength));
    }
  }
  const unsigned char* base = buffer.data() + view.byteOffset + a.byteOffset;
  for (std::size_t e = 0; e < a.count; ++e) {
    for (int c = 0; c < out.components; ++c) {
      out.values[e * out.components + c] =
          component(base + e * stride + c * csize, a.componentType, a.normalized);
    }
  }
  return out;
}

}  // namespace lt::gltf
