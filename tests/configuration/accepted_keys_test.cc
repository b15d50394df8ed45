#include "configuration/accepted_keys.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace stereonav {
namespace {

using SectionKey = std::pair<std::string, std::string>;

// The keys a configuration document lists: under a heading "### [section]", every table row
// whose first cell is a `key` in backticks. Any other heading ends the section.
std::set<SectionKey> documentedKeys(std::istream& document) {
  std::set<SectionKey> keys;
  std::string section, line;
  while (std::getline(document, line)) {
    if (line.rfind("#", 0) == 0) {
      const size_t open = line.find("### [");
      const size_t close = line.rfind(']');
      section = open == 0 && close != std::string::npos ? line.substr(5, close - 5) : "";
      continue;
    }
    if (section.empty() || line.rfind("| `", 0) != 0) continue;
    const size_t end = line.find('`', 3);
    if (end != std::string::npos) keys.emplace(section, line.substr(3, end - 3));
  }
  return keys;
}

std::set<SectionKey> flatten(const IniKeyRecorder::Sections& sections) {
  std::set<SectionKey> keys;
  for (const auto& [section, section_keys] : sections) {
    for (const auto& entry : section_keys) keys.emplace(section, entry.first);
  }
  return keys;
}

std::string listOf(const std::set<SectionKey>& keys) {
  std::string text;
  for (const auto& [section, key] : keys) text += "  [" + section + "] " + key + "\n";
  return text;
}

TEST(DocumentedKeys, ReadsKeyRowsUnderSectionHeadingsOnly) {
  std::istringstream document(
      "# Configuration\n| `not_a_key` | x |\n### [stereo]\nprose with `code`\n| key | type |\n|---|---|\n"
      "| `window` | integer |\n| `max_disparity` | integer |\n### [wall.<name>]\n| `points` | text |\n"
      "## Files\n| `explore_160x120.ini` | ... |\n");
  const std::set<SectionKey> expected{{"stereo", "window"}, {"stereo", "max_disparity"}, {"wall.<name>", "points"}};
  EXPECT_EQ(documentedKeys(document), expected);
}

TEST(AcceptedConfigKeys, HoldsKeysEachKindOfLoaderReads) {
  const std::set<SectionKey> accepted = flatten(acceptedConfigKeys());
  // One key per loader, each read in a different way: a plain getter, a key read only when
  // present (has), a key only declared (a world object's), a section named by the user, and a
  // key read outside its options struct.
  for (const SectionKey& key : std::set<SectionKey>{{"stereo", "max_disparity"},
                                                    {"texture.<name>", "scales_m"},
                                                    {"world", "start_pose"},
                                                    {"wall.<name>", "points"},
                                                    {"moving.<name>", "size"},
                                                    {"<map>_insertOpts", "update_step"},
                                                    {"<map>_creationOpts", "resolution"},
                                                    {"explorer", "pose_source"},
                                                    {"rawlog", "sensor_label"},
                                                    {"sim_robot", "radius_m"}}) {
    EXPECT_TRUE(accepted.count(key)) << "[" << key.first << "] " << key.second;
  }
  EXPECT_FALSE(accepted.count({"stereo", "pose_source"}));
}

TEST(AcceptedConfigKeys, RecordsTypesAndDefaults) {
  const IniKeyRecorder::Sections sections = acceptedConfigKeys();
  EXPECT_EQ(sections.at("stereo").at("window").type, "integer");
  EXPECT_EQ(sections.at("stereo").at("left_right_check").type, "bool");
  EXPECT_EQ(sections.at("table.<name>").at("height").default_value, "0.72");
  EXPECT_EQ(sections.at("spike_removal").at("filter").default_value, "segmentation");
}

// docs/configuration.md must list exactly the keys the loaders accept: a key added to a loader
// without a row here, or a row left after its key was removed, fails with the key named.
TEST(ConfigurationDoc, ListsEveryAcceptedKeyAndNoOther) {
  std::ifstream document(STEREONAV_CONFIGURATION_DOC);
  ASSERT_TRUE(document) << STEREONAV_CONFIGURATION_DOC << ": cannot read";
  const std::set<SectionKey> documented = documentedKeys(document);
  const std::set<SectionKey> accepted = flatten(acceptedConfigKeys());
  std::set<SectionKey> missing, extra;
  for (const SectionKey& key : accepted) {
    if (!documented.count(key)) missing.insert(key);
  }
  for (const SectionKey& key : documented) {
    if (!accepted.count(key)) extra.insert(key);
  }
  EXPECT_TRUE(missing.empty()) << "accepted but not in docs/configuration.md (build/bin/stereonav config "
                                  "--keys prints their rows):\n"
                               << listOf(missing);
  EXPECT_TRUE(extra.empty()) << "in docs/configuration.md but no loader reads them:\n" << listOf(extra);
}

}  // namespace
}  // namespace stereonav
