// "Did you mean": the known names closest to a name the user wrote, for the message that refuses
// it (an unknown parameter entry, selection value, region, panel, command or option).
#pragma once

#include <string>
#include <vector>

namespace tightfit {

// The number of single-character insertions, deletions, substitutions and swaps of two
// neighbours that turn `a` into `b`, ignoring case (the optimal string alignment distance).
std::size_t edit_distance(const std::string& a, const std::string& b);

// The known names nearest to `unknown`, nearest first (at most `limit`): those within a third of
// the longer name's length in edits (at least one, never all of it), or that contain the other
// name ignoring case (three letters or more).
std::vector<std::string> closest_names(const std::string& unknown,
                                       const std::vector<std::string>& known,
                                       std::size_t limit = 3);

// The end of a refusal: "; did you mean 'Law'?" when a name is close; otherwise, for up to
// `list_up_to` known names, "; known: a, b, c"; else "".
std::string did_you_mean(const std::string& unknown, const std::vector<std::string>& known,
                         std::size_t list_up_to = 12);

}  // namespace tightfit
