// What an import mapped and what it left out, one line each ("mapped /materials/0/... -> ...",
// "ignored /materials/0/normalTexture: ..."), printed by `ltrender info`: nothing is dropped
// silently.
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lt::gltf {

using Notes = std::vector<std::string>;

// Adds "ignored PTR/KEY: WHY" for every key of `object` not in `mapped` ("name" and "extras"
// count as mapped: they change nothing). Extensions are listed one by one, except those named
// in `mapped` too.
void note_unmapped_keys(const nlohmann::json& object, const std::string& pointer,
                        std::initializer_list<const char*> mapped, const std::string& why,
                        Notes& notes);

// The JSON value at `pointer` (RFC 6901), or null when absent.
const nlohmann::json& at_pointer(const nlohmann::json& doc, const std::string& pointer);

// A number at `key` of `object`, `def` when absent; an InputError naming PTR/KEY when it is not
// a finite number in [lo, hi].
double bounded_number(const nlohmann::json& object, const char* key, double def, double lo,
                      double hi, const std::string& file, const std::string& pointer);

// An array of `n` numbers at `key` (colours, factors), each in [lo, hi]; `def` when absent.
std::vector<double> bounded_numbers(const nlohmann::json& object, const char* key, std::size_t n,
                                    std::vector<double> def, double lo, double hi,
                                    const std::string& file, const std::string& pointer);

}  // namespace lt::gltf
