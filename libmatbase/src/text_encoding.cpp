#include "matbase/text_encoding.h"

#include <array>
#include <cstdint>
#include <cstdio>

namespace matbase {
namespace {

struct Mark {
  std::string_view bytes;
  const char* name;
  int unit;  // bytes per code unit
  bool big_endian;
};

// UTF-32's little-endian mark begins with UTF-16's, so it is tested first.
const std::array<Mark, 5> kMarks = {{{std::string_view("\xFF\xFE\0\0", 4), "UTF-32 (little-endian)", 4, false},
                                     {std::string_view("\0\0\xFE\xFF", 4), "UTF-32 (big-endian)", 4, true},
                                     {std::string_view("\xEF\xBB\xBF", 3), "UTF-8", 1, false},
                                     {std::string_view("\xFF\xFE", 2), "UTF-16 (little-endian)", 2, false},
                                     {std::string_view("\xFE\xFF", 2), "UTF-16 (big-endian)", 2, true}}};

const Mark* mark_of(std::string_view bytes) {
  for (const Mark& mark : kMarks)
    if (bytes.substr(0, mark.bytes.size()) == mark.bytes) return &mark;
  return nullptr;
}

uint32_t code_unit(std::string_view bytes, size_t at, const Mark& mark) {
  uint32_t value = 0;
  for (int k = 0; k < mark.unit; ++k) {
    const auto byte = static_cast<uint8_t>(bytes[at + static_cast<size_t>(mark.big_endian ? k : mark.unit - 1 - k)]);
    value = (value << 8) | byte;
  }
  return value;
}

void append_utf8(uint32_t code_point, std::string& out) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

std::string at_byte(const char* problem, size_t byte) {
  return std::string(problem) + " at byte " + std::to_string(byte);
}

}  // namespace

std::optional<std::string> byte_order_mark(std::string_view bytes) {
  const Mark* mark = mark_of(bytes);
  if (!mark) return std::nullopt;
  return std::string(mark->name);
}

std::optional<std::string> decode_marked_text(std::string_view bytes, std::string& text) {
  const Mark* mark = mark_of(bytes);
  if (!mark) {
    text = std::string(bytes);
    return std::nullopt;
  }
  const std::string_view body = bytes.substr(mark->bytes.size());
  if (mark->unit == 1) {
    text = std::string(body);
    return std::nullopt;
  }
  const auto unit = static_cast<size_t>(mark->unit);
  const std::string marked = "the text starts with a byte-order mark of " + std::string(mark->name) + ", but ";
  if (body.size() % unit != 0)
    return marked + "its length (" + std::to_string(bytes.size()) + " bytes) is not a whole number of " +
           std::to_string(unit) + "-byte units";
  text.clear();
  text.reserve(body.size() / unit);
  for (size_t at = 0; at < body.size(); at += unit) {
    const size_t byte = at + mark->bytes.size();
    uint32_t code_point = code_unit(body, at, *mark);
    if (unit == 2 && code_point >= 0xD800 && code_point < 0xDC00) {
      const uint32_t low = at + 2 < body.size() ? code_unit(body, at + 2, *mark) : 0;
      if (!(low >= 0xDC00 && low < 0xE000)) return marked + at_byte("it has an unpaired UTF-16 surrogate", byte);
      code_point = 0x10000 + ((code_point - 0xD800) << 10) + (low - 0xDC00);
      at += 2;
    } else if ((code_point >= 0xD800 && code_point < 0xE000) || code_point > 0x10FFFF) {
      return marked + at_byte(unit == 2 ? "it has an unpaired UTF-16 surrogate" : "it has a UTF-32 unit that is no character", byte);
    }
    append_utf8(code_point, text);
  }
  return std::nullopt;
}

size_t utf8_sequence_length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  const uint8_t lead = byte(i);
  if (lead < 0x80) return 1;
  size_t length = 0;
  uint32_t code_point = 0;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2, code_point = lead & 0x1F;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, code_point = lead & 0x0F;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, code_point = lead & 0x07;
  else return 0;
  if (i + length > text.size()) return 0;
  for (size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code_point = (code_point << 6) | (byte(i + k) & 0x3F);
  }
  // No overlong forms, no surrogates, nothing past U+10FFFF.
  const bool overlong = (length == 3 && code_point < 0x800) || (length == 4 && code_point < 0x10000);
  if (overlong || (code_point >= 0xD800 && code_point < 0xE000) || code_point > 0x10FFFF) return 0;
  return length;
}

std::string valid_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const size_t length = utf8_sequence_length(text, i);
    if (length > 0) {
      out.append(text.substr(i, length));
      i += length;
      continue;
    }
    char escaped[5];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<uint8_t>(text[i]));
    out += escaped;
    ++i;
  }
  return out;
}

}  // namespace matbase
