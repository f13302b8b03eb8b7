#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace gi {

// UTF-8 (RFC 3629), the encoding scene files and OBJ files must be in: what the
// readers need to refuse other bytes and to count columns in characters.

// The length of the UTF-8 sequence that starts at text[i] (1 to 4 bytes), or 0 if
// the bytes there are not one: no overlong forms, no surrogates, nothing past U+10FFFF.
std::size_t utf8_length(std::string_view text, std::size_t i);

// Appends the code point's UTF-8 bytes (a \uXXXX escape of a JSON string).
void append_utf8(std::string& out, unsigned code);

// Is the text UTF-8? If not, `bad_column` gets the column (in characters, from 1) of
// the first byte that is not.
bool is_utf8(std::string_view text, int* bad_column = nullptr);

// The text as one readable line, for a message that quotes input (a name from a scene
// file, a word of a mesh file, an option's value): control characters (C0 and C1),
// which would cut or split the line or drive the terminal, the bidirectional overrides
// and isolates (U+202A-U+202E, U+2066-U+2069), which would show the line reordered,
// and bytes that are not UTF-8 are written \xNN, byte by byte; other UTF-8
// characters stay as they are.
std::string printable(std::string_view text);

}  // namespace gi
