#pragma once

#include <string>

namespace stereonav {

// The one line of an exception message worth showing a user. Ours are one line already; MRPT's
// carry a banner, the throwing function's location and a backtrace over many lines, of which the
// message is the last line before the backtrace that says something. The whole text is for
// --verbose.
std::string oneLineMessage(const std::string& message);

}  // namespace stereonav
