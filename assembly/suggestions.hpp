#pragma once
// "Did you mean": the known name closest to a misspelt one, as git and cargo suggest, for the messages
// that refuse an unknown key or registered name ("...(known: c_nu, c_tau); did you mean 'c_nu'?").
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pc {

// The edits (insert, delete, substitute a character, or swap two adjacent ones) that turn a into b: the
// optimal string alignment distance, so that a transposed pair ("linaer") is one typo, not two.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The known names nearest to `name`, if they are close: at most max(1, size / 3) edits, `size` the longer
// of the two names' lengths; every name at that least distance, in `known`'s order ("PZT-5X": PZT-5A and
// PZT-5H). None when no name is that close, or `name` is itself known.
std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& known);

// "; did you mean 'c_nu'?" (or "'PZT-5A' or 'PZT-5H'") when known names are close to `name`, else empty:
// to append to a message that lists the known names.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& known);

// "'PZT-5A' or 'PZT-5H'": the closest names quoted, empty when there are none.
std::string quoted_alternatives(const std::vector<std::string>& names);

}  // namespace pc
