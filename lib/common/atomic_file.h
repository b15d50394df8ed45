#pragma once

#include <functional>
#include <string>

namespace stereonav {

// Writes `path` through `write_to`, which receives a temporary path in the same directory and
// must create the file there; the temporary is then renamed over `path`, so readers never see a
// half-written output and an interrupted run leaves the previous file intact. Throws
// std::runtime_error naming `path` if writing or renaming fails.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporary_path)>& write_to);

// Convenience for text and binary blobs.
void writeStringAtomically(const std::string& path, const std::string& contents);

}  // namespace stereonav
