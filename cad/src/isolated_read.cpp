// The child process that reads a CAD file (see isolated_read.h): its limits,
// the message it sends back through a pipe, and the parent's watch over it.
#include "isolated_read.h"

#include <BinTools.hxx>
#include <Standard_OutOfMemory.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <sstream>

#include "cpu_time.h"
#include "exact_placements.h"

#if defined(__unix__) || defined(__APPLE__)
#define RDMESH_CAN_FORK 1
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#endif
#if defined(__linux__)
#include <sys/prctl.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define RDMESH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RDMESH_ASAN 1
#endif
#endif

namespace rdmesh::cad {
namespace {

// ---- The message: magic, outcome, text, log lines, solid names, face names and
// colours, shape, its exact placements, end mark. Solids are numbered in
// TopExp_Explorer order, faces in TopExp::MapShapes order: both are the same
// on the shape read back.

constexpr char kMagic[] = "rdmesh-cad-read-2";
constexpr char kEnd[] = "end";

enum class Outcome : char {
  shape = 'S',          // the read shape follows
  input_error = 'E',    // the text is the InputError's problem
  out_of_memory = 'M',  // an allocation failed under the memory limit
};

class Encoder {
 public:
  void number(std::uint64_t v) { out_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void text(const std::string& s) {
    number(s.size());
    out_ += s;
  }
  std::string& out() { return out_; }

 private:
  std::string out_;
};

class Decoder {
 public:
  explicit Decoder(const std::string& in) : in_(in) {}
  bool number(std::uint64_t& v) {
    if (in_.size() - pos_ < sizeof v) return false;
    std::memcpy(&v, in_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return true;
  }
  bool text(std::string& s) {
    std::uint64_t n = 0;
    if (!number(n) || in_.size() - pos_ < n) return false;
    s.assign(in_, pos_, n);
    pos_ += n;
    return true;
  }
  bool done() const { return pos_ == in_.size(); }

 private:
  const std::string& in_;
  std::size_t pos_ = 0;
};

struct Message {
  Outcome outcome = Outcome::input_error;
  std::string text;  // the problem of an InputError
  ReadShape read;
};

std::string encode(Outcome outcome, const std::string& text, const ReadShape* read) {
  Encoder e;
  e.text(kMagic);
  e.text(std::string(1, static_cast<char>(outcome)));
  e.text(text);
  std::vector<std::string> names;
  std::ostringstream shape;
  std::string placements;
  if (read) {
    for (TopExp_Explorer ex(read->shape, TopAbs_SOLID); ex.More(); ex.Next()) {
      names.emplace_back();
      for (const auto& [solid, name] : read->solid_names) {
        if (solid.IsSame(ex.Current())) names.back() = name;
      }
    }
    BinTools::Write(read->shape, shape, Standard_False, Standard_False,
                    BinTools_FormatVersion_CURRENT);
    placements = save_placements(read->shape);
  }
  e.number(read ? read->log.size() : 0);
  if (read) {
    for (const std::string& line : read->log) e.text(line);
  }
  e.number(names.size());
  for (const std::string& name : names) e.text(name);
  std::vector<ShapeStyle> styles;
  if (read) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(read->shape, TopAbs_FACE, faces);
    styles.resize(static_cast<std::size_t>(faces.Extent()));
    for (const auto& [face, style] : read->face_styles) {
      const int i = faces.FindIndex(face);
      if (i > 0) styles[static_cast<std::size_t>(i - 1)] = style;
    }
  }
  e.number(styles.size());
  for (const ShapeStyle& style : styles) {
    e.text(style.name);
    e.text(style.color);
  }
  e.text(shape.str());
  e.text(placements);
  e.text(kEnd);
  return std::move(e.out());
}

// False when the message is truncated or malformed (the child died writing it).
bool decode(const std::string& in, Message& m) {
  Decoder d(in);
  std::string magic, outcome, shape, placements, end;
  std::uint64_t n = 0;
  if (!d.text(magic) || magic != kMagic || !d.text(outcome) || outcome.size() != 1) return false;
  m.outcome = static_cast<Outcome>(outcome[0]);
  if (!d.text(m.text) || !d.number(n)) return false;
  m.read.log.resize(n);
  for (std::string& line : m.read.log) {
    if (!d.text(line)) return false;
  }
  std::vector<std::string> names;
  if (!d.number(n) || n > in.size()) return false;
  names.resize(n);
  for (std::string& name : names) {
    if (!d.text(name)) return false;
  }
  std::vector<ShapeStyle> styles;
  if (!d.number(n) || n > in.size()) return false;
  styles.resize(n);
  for (ShapeStyle& style : styles) {
    if (!d.text(style.name) || !d.text(style.color)) return false;
  }
  if (!d.text(shape) || !d.text(placements) || !d.text(end) || end != kEnd || !d.done()) {
    return false;
  }
  if (m.outcome != Outcome::shape) return true;
  std::istringstream stream(shape);
  BinTools::Read(m.read.shape, stream);
  if (!restore_placements(m.read.shape, placements)) return false;
  std::size_t i = 0;
  for (TopExp_Explorer ex(m.read.shape, TopAbs_SOLID); ex.More(); ex.Next(), ++i) {
    if (i >= names.size()) return false;
    if (!names[i].empty()) m.read.solid_names.emplace_back(ex.Current(), names[i]);
  }
  if (i != names.size()) return false;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(m.read.shape, TopAbs_FACE, faces);
  if (static_cast<std::size_t>(faces.Extent()) != styles.size()) return false;
  for (std::size_t k = 0; k < styles.size(); ++k) {
    if (!styles[k].name.empty() || !styles[k].color.empty()) {
      m.read.face_styles.emplace_back(faces(static_cast<int>(k) + 1), styles[k]);
    }
  }
  return true;
}

// The problem of an InputError about `path`, without the "path: " prefix.
std::string problem_of(const InputError& e, const std::string& path) {
  const std::string what = e.what();
  const std::string prefix = path + ": ";
  if (e.file() == path && what.compare(0, prefix.size(), prefix) == 0) {
    return what.substr(prefix.size());
  }
  return what;
}

#ifdef RDMESH_CAN_FORK

double time_limit(const CadOptions& options, const std::string& path) {
  return read_time_limit_seconds(options, path);
}

// ---- The child.

void write_all(int fd, const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

// Nothing the child prints may reach the user (OpenCASCADE's own output, a
// sanitizer's report of the crash), and it keeps no other file of the parent's
// (say the pipe of another thread's reading child). Its pipe becomes fd 3.
void detach_files(int& fd) {
  const int moved = ::fcntl(fd, F_DUPFD, 3);  // out of the way of 0..2
  if (moved >= 0) fd = moved;
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    for (int std_fd = 0; std_fd <= 2; ++std_fd) ::dup2(null, std_fd);
  }
  if (fd != 3 && ::dup2(fd, 3) == 3) fd = 3;
  for (int other = 4; other < 1024; ++other) ::close(other);
}

#ifndef RDMESH_ASAN
// Virtual memory the process has mapped already (the parent's heap included).
std::uint64_t mapped_bytes() {
  std::uint64_t pages = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    unsigned long long p = 0;
    if (std::fscanf(f, "%llu", &p) == 1) pages = p;
    std::fclose(f);
  }
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}
#endif

void limit(int resource, std::uint64_t soft, std::uint64_t hard) {
  rlimit r{};
  if (::getrlimit(resource, &r) != 0) return;
  const auto below = [&](std::uint64_t v) {
    return r.rlim_max == RLIM_INFINITY ? static_cast<rlim_t>(v)
                                       : std::min(static_cast<rlim_t>(v), r.rlim_max);
  };
  r.rlim_cur = below(soft);
  r.rlim_max = below(hard);
  ::setrlimit(resource, &r);
}

void apply_limits(const CadOptions& options, double seconds) {
  limit(RLIMIT_CORE, 0, 0);  // a crash writes no core file
  // A backstop for a child whose parent is gone: the parent watches the same clock.
  const auto cpu = static_cast<std::uint64_t>(std::ceil(seconds)) + 2;
  limit(RLIMIT_CPU, cpu, cpu + 1);
#ifndef RDMESH_ASAN
  std::uint64_t budget = std::uint64_t{options.read_memory_limit_mib} << 20;
  if (budget == 0) {
    budget = static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) *
             static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE)) / 2;
  }
  limit(RLIMIT_AS, mapped_bytes() + budget, mapped_bytes() + budget);
#else
  (void)options;  // the sanitizer reserves far more address space than it uses
#endif
}

[[noreturn]] void run_child(int fd, pid_t parent, const std::string& path, double limit_seconds,
                            const std::function<ReadShape()>& read, const CadOptions& options) {
#if defined(__linux__)
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // the parent gone, so is the child
#endif
  if (::getppid() != parent) ::_exit(3);  // it went before the line above
  detach_files(fd);
  apply_limits(options, limit_seconds);
  try {
    std::string message;
    try {
      const ReadShape r = read();
      message = encode(Outcome::shape, {}, &r);
    } catch (const InputError& e) {
      message = encode(Outcome::input_error, problem_of(e, path), nullptr);
    } catch (const std::bad_alloc&) {
      message = encode(Outcome::out_of_memory, {}, nullptr);
    } catch (const Standard_OutOfMemory&) {
      message = encode(Outcome::out_of_memory, {}, nullptr);
    } catch (const Standard_Failure& e) {
      message = encode(Outcome::input_error, "OpenCASCADE failed to read the model: " + describe(e),
                       nullptr);
    } catch (const std::exception& e) {
      message =
          encode(Outcome::input_error, std::string("the reader failed: ") + e.what(), nullptr);
    }
    write_all(fd, message);
    ::close(fd);  // the parent reads on while this process's memory is torn down
  } catch (...) {
    ::_exit(3);  // no message: the parent reports a crash
  }
  ::_exit(0);
}

// ---- The parent.

/// Kills and reaps the child on every path that does not reap it.
class ChildGuard {
 public:
  explicit ChildGuard(pid_t pid) : pid_(pid) {}
  ~ChildGuard() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    reap();
  }
  ChildGuard(const ChildGuard&) = delete;
  ChildGuard& operator=(const ChildGuard&) = delete;
  /// Waits for the child to end and returns its wait status.
  int reap() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

 private:
  pid_t pid_;
};

/// Closes a file descriptor on every path.
struct FdGuard {
  int fd = -1;
  ~FdGuard() {
    if (fd >= 0) ::close(fd);
  }
};

/// How reading in the child ended, as the parent saw it.
enum class Drain { closed, out_of_cpu, out_of_wall };

/// Appends what child `pid` writes to `out` until it closes the pipe, has used
/// `cpu_limit` CPU seconds, or `wall_limit` seconds have passed (a child
/// waiting without computing). The child's CPU clock is read at least every
/// 50 ms, and at once when the pipe has news.
Drain drain(int fd, pid_t pid, std::string& out, double cpu_limit, double wall_limit) {
  using Clock = std::chrono::steady_clock;
  const auto wall_end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(wall_limit));
  char buffer[1 << 16];
  for (;;) {
    const double cpu = process_cpu_seconds(pid);
    if (cpu > cpu_limit) return Drain::out_of_cpu;
    const auto wall_left = std::chrono::ceil<std::chrono::milliseconds>(wall_end - Clock::now());
    if (wall_left.count() <= 0) return Drain::out_of_wall;
    // The child cannot use more CPU than wall time: no need to look sooner.
    const double cpu_left_ms = cpu < 0 ? 50.0 : std::ceil(1000 * (cpu_limit - cpu));
    const auto wait_ms = std::min<long long>(
        {wall_left.count(), 50, static_cast<long long>(std::max(1.0, cpu_left_ms))});
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(wait_ms));
    if (ready < 0 && errno != EINTR) return Drain::closed;  // cannot watch: judge the status
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return Drain::closed;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

std::string seconds(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

#endif  // RDMESH_CAN_FORK

}  // namespace

ReadShape read_in_child(const std::string& path, const std::string& format,
                        const std::function<ReadShape()>& read, const CadOptions& options) {
#ifndef RDMESH_CAN_FORK
  (void)format;
  (void)options;
  return read();
#else
  const std::string cannot = "cannot read the file: the " + format + " reader ";
  // Once: the file's size sets it, and the message, the child's CPU limit and
  // the parent's wait must agree.
  const double limit_seconds = time_limit(options, path);
  const std::string timed_out = cannot + "did not finish within " + seconds(limit_seconds) +
                                " s of computing (malformed file?)";
  int fds[2];
  if (::pipe(fds) != 0) return read();  // no isolation possible: read here
  FdGuard in{fds[0]}, out{fds[1]};
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return read();
  if (pid == 0) run_child(fds[1], parent, path, limit_seconds, read, options);
  ChildGuard child(pid);
  ::close(out.fd);
  out.fd = -1;
  std::string bytes;
  // The limit is the child's CPU time; a child waiting without computing
  // (a blocked read) is stopped after ten times as long plus a minute.
  const double wall_limit = 10 * limit_seconds + 60;
  switch (drain(in.fd, pid, bytes, limit_seconds, wall_limit)) {
    case Drain::out_of_cpu:
      throw InputError(path, timed_out);
    case Drain::out_of_wall:
      throw InputError(path, cannot + "was still waiting after " + seconds(wall_limit) +
                                 " s without finishing (a file that is never complete?)");
    case Drain::closed:
      break;
  }
  // A complete message is the child's answer, whatever its end; else its end tells.
  Message m;
  bool complete = false;
  try {
    complete = decode(bytes, m);
  } catch (const Standard_Failure&) {
  }
  const int status = child.reap();
  if (!complete && WIFSIGNALED(status)) {
    // SIGKILL not from us: the kernel's out-of-memory killer; SIGXCPU: the CPU backstop.
    if (WTERMSIG(status) == SIGKILL) throw InputError(path, cannot + "ran out of memory");
    if (WTERMSIG(status) == SIGXCPU) throw InputError(path, timed_out);
  }
  if (!complete) throw InputError(path, cannot + "crashed (malformed file?)");
  if (m.outcome == Outcome::out_of_memory) throw InputError(path, cannot + "ran out of memory");
  if (m.outcome != Outcome::shape) throw InputError(path, m.text);
  return std::move(m.read);
#endif
}

double read_time_limit_seconds(const CadOptions& options, const std::string& path) {
  if (options.read_time_limit > 0) return std::min(options.read_time_limit, 1e9);
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  const double mb = ec ? 0.0 : static_cast<double>(bytes) / 1e6;
  return std::min(std::round(10.0 + 20.0 * mb), 1e9);  // whole seconds, for the messages
}

}  // namespace rdmesh::cad
