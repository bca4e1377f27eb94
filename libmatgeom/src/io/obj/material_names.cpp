#include "io/obj/material_names.h"

#include <cstddef>

#include "io/obj/statement_text.h"

namespace matgeom::obj {

std::string_view statement_name(std::string_view line) {
  const std::string_view rest = after_keyword(parsed_part(line));
  const size_t end = rest.find_last_not_of(" \t\r\n");
  return end == std::string_view::npos ? std::string_view() : rest.substr(0, end + 1);
}

std::string name_word(std::string_view name) {
  std::string word;
  for (const char c : name) {
    if (c == ' ') word += "%20";
    else if (c == '\t') word += "%09";
    else if (c == '%') word += "%25";
    else word += c;
  }
  return word;
}

std::string word_name(std::string_view word) {
  std::string name;
  for (size_t i = 0; i < word.size(); ++i) {
    const std::string_view code = word.substr(i, 3);
    if (code == "%20") name += ' ';
    else if (code == "%09") name += '\t';
    else if (code == "%25") name += '%';
    else {
      name += word[i];
      continue;
    }
    i += 2;
  }
  return name;
}

}  // namespace matgeom::obj
