#pragma once
// Text files other tools write, and the messages that quote them. Windows tools save text as
// UTF-16 (Notepad's "Unicode") or with a UTF-8 byte-order mark; a file's bytes may be in any
// 8-bit code page (a Latin-1 material name), which quoted as they are would make a message that is
// not valid UTF-8.
#include <optional>
#include <string>
#include <string_view>

namespace matbase {

// The text of a file as UTF-8, told by its byte-order mark: a UTF-8 mark is dropped, UTF-16 and
// UTF-32 (little- or big-endian) are converted; text without a mark is returned as it is.
// Returns the problem instead, a sentence a reader's message takes as it is ("the text starts with
// a byte-order mark of UTF-16 (little-endian), but it has an unpaired UTF-16 surrogate at byte 12"),
// when the marked encoding does not hold.
std::optional<std::string> decode_marked_text(std::string_view bytes, std::string& text);

// The name of the byte-order mark `bytes` starts with ("UTF-16 (little-endian)"), if any.
std::optional<std::string> byte_order_mark(std::string_view bytes);

// `text` with every byte that is not part of a valid UTF-8 sequence written as \xNN; valid text
// is returned unchanged.
std::string valid_utf8(std::string_view text);

// The length of the valid UTF-8 sequence starting at text[i] (1 to 4), or 0 when the byte there
// starts none.
size_t utf8_sequence_length(std::string_view text, size_t i);

}  // namespace matbase
