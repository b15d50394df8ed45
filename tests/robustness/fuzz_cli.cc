// Black-box campaign through the command line (issue 24): mutated rawlogs through `stereonav map`
// and mutated ini, world and path files through `map` and `simulate`. Every run must end in a
// map (exit 0), a partial map (3, the rawlog named) or a one-line error naming the mutated file
// (1 or 2); never a signal, a hang or a multi-line error. Prints the counts and every failure;
// exits non-zero if there was one.
//
//   fuzz_cli <repo root> <work dir> [rawlog cases] [text cases] [seed]
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.h"

namespace {

namespace fs = std::filesystem;
using stereonav::CommandRun;
using stereonav::runStereonav;

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeAll(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Byte-level mutations for binary files: bit flips, insertions, deletions, truncation, splices
// (a block copied from elsewhere in the file), each applied 1..4 times.
std::string mutateBytes(std::string bytes, std::mt19937& random) {
  std::uniform_int_distribution<int> count(1, 4);
  const int mutations = count(random);
  for (int m = 0; m < mutations && !bytes.empty(); ++m) {
    std::uniform_int_distribution<size_t> at(0, bytes.size() - 1);
    switch (random() % 5) {
      case 0:
        bytes[at(random)] ^= static_cast<char>(1 << (random() % 8));
        break;
      case 1:
        bytes.insert(at(random), std::string(1 + random() % 64, static_cast<char>(random())));
        break;
      case 2: {
        const size_t from = at(random);
        bytes.erase(from, std::min<size_t>(1 + random() % 2000, bytes.size() - from));
        break;
      }
      case 3:
        bytes.resize(at(random));
        break;
      default: {
        const size_t from = at(random), to = at(random);
        const size_t length = std::min<size_t>({1 + random() % 4096, bytes.size() - from});
        bytes.insert(to, bytes.substr(from, length));
        break;
      }
    }
  }
  return bytes;
}

// Text mutations for ini, world and path files: a number replaced by an extreme one, a line
// deleted or duplicated, a character changed, or a byte-level mutation.
std::string mutateText(std::string text, std::mt19937& random) {
  static const std::vector<std::string> kExtremes{"nan", "inf", "-inf", "1e308", "-1e308", "1e-308", "0", "-1",
                                                  "2147483647", "2147483648", "-2147483649", "1,5", "0.1abc",
                                                  "0.1 0.2", "1e9", "", "99999999999999999999"};
  std::vector<size_t> numbers;
  for (size_t i = 0; i < text.size(); ++i) {
    const bool starts = (text[i] >= '0' && text[i] <= '9') && (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])));
    if (starts) numbers.push_back(i);
  }
  const int kind = static_cast<int>(random() % 6);
  if (kind <= 2 && !numbers.empty()) {
    const size_t at = numbers[random() % numbers.size()];
    size_t end = at;
    while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
                                 text[end] == 'e' || text[end] == '-')) {
      ++end;
    }
    text.replace(at, end - at, kExtremes[random() % kExtremes.size()]);
    return text;
  }
  if (kind == 3) {
    std::vector<size_t> starts{0};
    for (size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') starts.push_back(i + 1);
    }
    const size_t line = starts[random() % starts.size()];
    const size_t end = text.find('\n', line);
    const std::string copy = text.substr(line, end == std::string::npos ? std::string::npos : end - line + 1);
    if (random() % 2) {
      text.erase(line, copy.size());
    } else {
      text.insert(line, copy);
    }
    return text;
  }
  return mutateBytes(text, random);
}

struct Tally {
  std::map<int, int> exits;
  int crashes = 0, hangs = 0, unclear = 0, runs = 0;
};

// Checks one run; `file` is the mutated input that must be named by any error.
void check(const CommandRun& run, const std::string& file, const std::string& what, Tally& tally) {
  ++tally.runs;
  ++tally.exits[run.exit_code];
  std::string problem;
  if (run.timed_out) {
    ++tally.hangs;
    problem = "hang";
  } else if (run.signal != 0 || run.exit_code < 0 || run.exit_code > 3) {
    ++tally.crashes;
    problem = "crash (signal " + std::to_string(run.signal) + ", exit " + std::to_string(run.exit_code) + ")";
  } else if ((run.exit_code == 1 || run.exit_code == 2) &&
             (!run.oneLineError() || run.err.find(fs::path(file).filename().string()) == std::string::npos)) {
    ++tally.unclear;
    problem = "error not one line naming the file";
  } else if (run.exit_code == 3 && run.err.find(fs::path(file).filename().string()) == std::string::npos) {
    ++tally.unclear;
    problem = "partial map without naming the file";
  }
  if (tally.runs % 50 == 0) {
    std::cout << "  " << tally.runs << " runs: " << tally.crashes << " crashes, " << tally.hangs << " hangs, "
              << tally.unclear << " unclear" << std::endl;
  }
  if (!problem.empty()) {
    std::cout << "FAIL " << what << ": " << problem << "; input kept as " << file << "\n" << run.err << "\n";
  } else {
    fs::remove(file);
  }
}

void print(const std::string& name, const Tally& tally) {
  std::cout << name << ": " << tally.runs << " runs, " << tally.crashes << " crashes, " << tally.hangs << " hangs, "
            << tally.unclear << " unclear errors; exit codes:";
  for (const auto& [code, count] : tally.exits) std::cout << " " << code << "x" << count;
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: fuzz_cli <repo root> <work dir> [rawlog cases=1000] [text cases=1000] [seed=1]\n";
    return 2;
  }
  const std::string root = argv[1], work = argv[2];
  const int rawlog_cases = argc > 3 ? std::stoi(argv[3]) : 1000;
  const int text_cases = argc > 4 ? std::stoi(argv[4]) : 1000;
  std::mt19937 random(argc > 5 ? static_cast<unsigned>(std::stoul(argv[5])) : 1u);
  fs::create_directories(work);
  const std::string repro = root + "/tests/data/repro/";
  const std::string config = repro + "map_resolution_comma.ini";  // made valid below
  std::string base_config = readAll(config);
  base_config.replace(base_config.find("resolution = 1,5"), 16, "resolution = 0.10");
  writeAll(work + "/base.ini", base_config);
  const std::string rawlog = readAll(repro + "office3.rawlog");
  stereonav::RunOptions options;
  options.timeout_s = 30.0;

  Tally rawlogs;
  for (int i = 0; i < rawlog_cases; ++i) {
    const std::string file = work + "/case" + std::to_string(i) + ".rawlog";
    writeAll(file, mutateBytes(rawlog, random));
    check(runStereonav({"map", "--config", work + "/base.ini", "--rawlog", file, "--out", work + "/out"}, options),
          file, "map --rawlog " + file, rawlogs);
  }
  print("mutated rawlogs (map)", rawlogs);

  // Text inputs: the map configuration, the world, the simulator configuration and the path.
  const std::vector<std::pair<std::string, std::string>> texts{
      {"map config", base_config}, {"world", readAll(repro + "world_mini.ini")},
      {"simulate config", readAll(repro + "simulate.ini")}, {"path", readAll(repro + "path_mini.txt")}};
  Tally text_tally;
  for (int i = 0; i < text_cases; ++i) {
    const auto& [kind, original] = texts[static_cast<size_t>(i) % texts.size()];
    const std::string file = work + "/case" + std::to_string(i) + (kind == "path" ? ".txt" : ".ini");
    writeAll(file, mutateText(original, random));
    CommandRun run;
    if (kind == "map config") {
      run = runStereonav({"map", "--config", file, "--rawlog", repro + "office3.rawlog", "--out", work + "/out"}, options);
    } else {
      const std::string world = kind == "world" ? file : repro + "world_mini.ini";
      const std::string sim = kind == "simulate config" ? file : repro + "simulate.ini";
      const std::string plan = kind == "path" ? file : repro + "path_mini.txt";
      run = runStereonav({"simulate", "--world", world, "--config", sim, "--path", plan, "--out",
                          work + "/sim.rawlog", "--gt-map", work + "/truth.yaml"},
                         options);
    }
    check(run, file, kind + " " + file, text_tally);
  }
  print("mutated ini/world/path files (map, simulate)", text_tally);
  const bool clean = rawlogs.crashes + rawlogs.hangs + rawlogs.unclear + text_tally.crashes + text_tally.hangs +
                         text_tally.unclear ==
                     0;
  return clean ? 0 : 1;
}
