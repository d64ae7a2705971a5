// User text in one-line messages: keys, strings, file names and options come from other people, so
// nothing they contain may break the line, move the cursor or truncate the message.
#pragma once

#include <string>
#include <string_view>

namespace impact3d::case_format {

// The text with every control character (C0, DEL, C1), and every byte that is not part of valid
// UTF-8, written as an escape: \n, \t, \r, \xNN for bytes, \u{NN} for C1 characters. Everything else,
// backslashes included, is kept, so ordinary text and paths read as written.
std::string printable(std::string_view text);

// The text as a double-quoted string for a message: printable() plus \" and \\, so that the quoted
// text is unambiguous.
std::string quoted(std::string_view text);

// Whether `text` is valid UTF-8 (no overlong forms, no surrogates, at most U+10FFFF).
bool valid_utf8(std::string_view text);

}  // namespace impact3d::case_format
