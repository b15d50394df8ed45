#include "common/error_text.h"

#include <vector>

namespace stereonav {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  size_t begin = 0;
  while (begin <= text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    line.erase(0, line.find_first_not_of(" \t"));
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    result.push_back(line);
    begin = end + 1;
  }
  return result;
}

}  // namespace

std::string oneLineMessage(const std::string& message) {
  if (message.find('\n') == std::string::npos) return message;
  // MRPT 2.5: "==== MRPT exception ====", "Message:  <what>", "Location: ...", a backtrace; a
  // rethrow nests the original report under "Original exception:". The outermost message says
  // which object was being read, the innermost what went wrong.
  constexpr const char* kMessage = "Message:";
  std::vector<std::string> messages;
  for (const std::string& line : lines(message)) {
    if (line.rfind(kMessage, 0) == 0) {
      std::string text = line.substr(std::string(kMessage).size());
      text.erase(0, text.find_first_not_of(' '));
      messages.push_back(text);
    }
  }
  if (!messages.empty()) {
    const std::string& innermost = messages.back();
    const std::string& outermost = messages.front();
    const std::string kParsing = "Exception while parsing typed object '";
    if (messages.size() > 1 && outermost.rfind(kParsing, 0) == 0) {
      const size_t end = outermost.find('\'', kParsing.size());
      return "reading " + outermost.substr(kParsing.size(), end - kParsing.size()) + ": " + innermost;
    }
    return innermost;
  }
  // Without a "Message:" line (MRPT's ini parser), the first line that is not the banner.
  for (const std::string& line : lines(message)) {
    if (!line.empty() && line.rfind("====", 0) != 0) return line;
  }
  return "";
}

}  // namespace stereonav
