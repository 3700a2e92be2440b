#pragma once
// Editing case-file text in tests: start from a built-in case and change one line.

#include <cstddef>
#include <string>
#include <string_view>

namespace revsph::testing {

// The text of a built-in case; throws std::logic_error if there is none of that name.
std::string builtin_case_text(std::string_view name);

// `from` must occur exactly once, so that an edit of the built-in case cannot silently land on
// another line (or nowhere) when that case changes.
std::string replaced_once(std::string text, std::string_view from, std::string_view to);

// 1-based line on which the character at `offset` lies.
int line_at(const std::string& text, std::size_t offset);

// `part` with "@LINE@" (its first occurrence) replaced by the line on which the last line of
// `edit` lies in `text`: for messages that point into an edited case file.
std::string with_edit_line(std::string part, const std::string& text, const std::string& edit);

} // namespace revsph::testing
