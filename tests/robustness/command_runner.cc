#include "command_runner.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace stereonav {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string CommandRun::errorText() const {
  std::string text = err;
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

bool CommandRun::oneLineError() const {
  const std::string text = errorText();
  return !text.empty() && text.find('\n') == std::string::npos;
}

CommandRun runStereonav(const std::vector<std::string>& arguments, const RunOptions& options) {
  const std::string program = std::string(STEREONAV_BINARY_DIR) + "/bin/stereonav";
  const auto stem = std::filesystem::temp_directory_path() / ("stereonav_run_" + std::to_string(::getpid()));
  const std::string out_path = stem.string() + ".out", err_path = stem.string() + ".err";
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) ::_exit(126);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    if (options.file_size_limit != RLIM_INFINITY) {
      std::signal(SIGXFSZ, SIG_IGN);
      rlimit limit{options.file_size_limit, options.file_size_limit};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  CommandRun run;
  int status = 0;
  rusage usage{};
  while (true) {
    const pid_t done = ::wait4(child, &status, WNOHANG, &usage);
    if (done == child) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > options.timeout_s && !run.timed_out) {
      run.timed_out = true;
      ::kill(child, SIGKILL);
    }
    if (options.while_running && !run.timed_out) options.while_running(child);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.cpu_seconds = usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec +
                    usage.ru_stime.tv_usec * 1e-6;
  run.peak_memory_mb = usage.ru_maxrss / 1024.0;
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  run.out = readFile(out_path);
  run.err = readFile(err_path);
  std::remove(out_path.c_str());
  std::remove(err_path.c_str());
  return run;
}

}  // namespace stereonav
