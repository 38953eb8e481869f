// Text as XML or HTML character data or attribute value (JUnit XML, the report page): the five
// markup characters escaped, and the control characters XML 1.0 cannot hold (all below 0x20 but
// tab, newline and return) dropped, so a scene name can never break the document.
#pragma once

#include <string>

namespace lt {

inline std::string markup_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        if (static_cast<unsigned char>(ch) >= 0x20 || ch == '\t' || ch == '\n' || ch == '\r')
          out += ch;
    }
  }
  return out;
}

}  // namespace lt
