#pragma once
/// \file
/// Text from a user's file or command line made safe to print on one line of a message.

#include <cstddef>
#include <string>
#include <string_view>

namespace tissu {

/// Offset of the first byte of `text` that is not part of a well-formed UTF-8 sequence (RFC 3629:
/// no overlong forms, no surrogates, nothing above U+10FFFF), or npos when it is all valid.
std::size_t invalid_utf8_offset(std::string_view text);

/// `text` with control characters written as JSON escapes (\n, \t, \u0001) and bytes that are
/// not valid UTF-8 as \xFF, so that it prints as one line of valid UTF-8; cut to about
/// `max_bytes` (at a character boundary) with "..." when longer.
std::string printable_text(std::string_view text, std::size_t max_bytes = 200);

}  // namespace tissu
