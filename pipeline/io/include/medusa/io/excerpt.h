// Input text quoted in an error message: at most ~200 characters, non-printable bytes escaped, so a
// binary file, a NUL byte or a 10 MB field gives one readable line.
#pragma once

#include <string>
#include <string_view>

namespace medusa::io {

// `text` with control bytes and bytes that are not valid UTF-8 written as \xNN (tab as \t), cut after
// `limit` characters with "... (<n> bytes in all)" added.
std::string excerpt(std::string_view text, std::size_t limit = 200);

} // namespace medusa::io
