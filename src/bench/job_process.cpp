#include "bench/job_process.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace tumble::bench {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) out.push_back(part);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

// The child: run each dt and write one line per result to `fd`.
[[noreturn]] void childMain(int fd, const BenchScene& scene, const EngineSetting& setting,
                            const RunOptions& options) {
  int code = 0;
  for (double dt : scene.dts) {
    RunResult r;
    try {
      r = runPoint(scene, setting, dt, options);
    } catch (const std::exception& e) {
      r = resultFor(scene, setting, dt);
      r.failed = true;
      r.wall_per_sim = NAN;
      r.note = std::string("failed: ") + e.what();
      code = 1;
    }
    std::cerr << "tumble-bench: " << scene.id << " " << setting.name << " 1/" << std::lround(1 / dt)
              << " s: " << r.wall_per_sim << " wall s per simulated s" << (r.cut ? " (cut)" : "")
              << (r.failed ? " " + r.note : "") << "\n";
    const std::string line = encodeResult(r) + "\n";
    for (std::size_t done = 0; done < line.size();) {
      const ssize_t n = write(fd, line.data() + done, line.size() - done);
      if (n <= 0) _exit(2);
      done += static_cast<std::size_t>(n);
    }
  }
  close(fd);
  _exit(code);   // no atexit handlers or stream flushes inherited from the parent
}

std::string describeStatus(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "exited with code " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

std::string encodeResult(const RunResult& r) {
  std::string metrics;
  for (const Metric& m : r.metrics) metrics += m.name + "=" + number(m.value) + ";";
  std::string note = r.note;
  for (char& c : note)
    if (c == '\t' || c == '\n') c = ' ';
  return r.scene + "\t" + r.setting + "\t" + r.engine + "\t" + number(r.dt) + "\t" +
         number(r.wall_per_sim) + "\t" + std::to_string(r.reps) + "\t" + number(r.simulated_s) +
         "\t" + (r.cut ? "1" : "0") + "\t" + number(r.peak_rss_mb) + "\t" + (r.failed ? "1" : "0") +
         "\t" + metrics + "\t" + note;
}

RunResult decodeResult(const std::string& line) {
  const std::vector<std::string> f = split(line, '\t');
  if (f.size() != 12) throw std::runtime_error("malformed result line: " + line);
  RunResult r;
  r.scene = f[0];
  r.setting = f[1];
  r.engine = f[2];
  r.dt = std::strtod(f[3].c_str(), nullptr);
  r.wall_per_sim = std::strtod(f[4].c_str(), nullptr);
  r.reps = std::atoi(f[5].c_str());
  r.simulated_s = std::strtod(f[6].c_str(), nullptr);
  r.cut = f[7] == "1";
  r.peak_rss_mb = std::strtod(f[8].c_str(), nullptr);
  r.failed = f[9] == "1";
  for (const std::string& m : split(f[10], ';')) {
    const std::size_t eq = m.find('=');
    if (eq != std::string::npos) r.metrics.push_back({m.substr(0, eq), std::strtod(m.c_str() + eq + 1, nullptr)});
  }
  r.note = f[11];
  return r;
}

std::vector<RunResult> runJobInChild(const BenchScene& scene, const EngineSetting& setting,
                                     const RunOptions& options) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("tumble-bench: cannot create a pipe");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("tumble-bench: cannot fork");
  if (pid == 0) {
    close(fds[0]);
    childMain(fds[1], scene, setting, options);
  }
  close(fds[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  std::vector<RunResult> results;
  for (const std::string& line : split(text, '\n'))
    if (!line.empty()) results.push_back(decodeResult(line));
  // Whatever the child did not report, it did not survive.
  for (std::size_t i = results.size(); i < scene.dts.size(); ++i) {
    RunResult r = resultFor(scene, setting, scene.dts[i]);
    r.failed = true;
    r.wall_per_sim = NAN;
    r.note = "engine process " + describeStatus(status);
    results.push_back(r);
  }
  return results;
}

}  // namespace tumble::bench
