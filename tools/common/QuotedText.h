// quotedText: a name or other user-given text as the command-line tools print it: in double
// quotes, with quotes, backslashes and control characters escaped (\" \\ \n \t \xHH), so a
// name is always data on one line and can never inject a line of its own into a listing.
#pragma once

#include <string>
#include <string_view>

namespace rgnav {

std::string quotedText(std::string_view text);

}  // namespace rgnav
