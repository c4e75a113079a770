#include "bench_support.hpp"

#include <dlfcn.h>
#include <malloc.h>
#include <stdlib.h>
#include <sched.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include <cholmod.h>

#include "symcontact/core/blas_kernels.hpp"

namespace symcontact::bench {

namespace {

std::string env_or_unset(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string("(unset)");
}

std::string resolved_path(const char* path) {
  char buf[PATH_MAX];
  if (!realpath(path, buf)) return std::string("(not found: ") + path + ")";
  return buf;
}

/// The value of "Key:" in a /proc file of "Key: value" lines, or "" when absent.
std::string proc_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size(), key) != 0) continue;
    const auto colon = line.find(':', key.size());
    if (colon == std::string::npos) continue;
    const auto start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? std::string() : line.substr(start);
  }
  return {};
}

/// A "1234 kB" field of /proc/self/status in MiB, or −1.
double status_mib(const std::string& key) {
  const std::string v = proc_field("/proc/self/status", key);
  if (v.empty()) return -1.0;
  return std::strtod(v.c_str(), nullptr) / 1024.0;
}

}  // namespace

MachineInfo machine_info() {
  MachineInfo m;
  m.online_cpus = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  cpu_set_t set;
  CPU_ZERO(&set);
  m.affinity_cpus = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : m.online_cpus;
  m.cpu_model = proc_field("/proc/cpuinfo", "model name");
  if (m.cpu_model.empty()) m.cpu_model = "(unknown)";
  const std::string mem = proc_field("/proc/meminfo", "MemTotal");
  m.mem_total_gib = std::strtod(mem.c_str(), nullptr) / (1024.0 * 1024.0);
  utsname u{};
  if (uname(&u) == 0) m.kernel = std::string(u.sysname) + " " + u.release;
#ifdef __VERSION__
  m.compiler = __VERSION__;
#endif
#ifdef NDEBUG
  m.assertions = false;
#else
  m.assertions = true;
#endif
  m.eigen_version = std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                    std::to_string(EIGEN_MINOR_VERSION);
  m.cholmod_version = std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
                      std::to_string(CHOLMOD_SUBSUB_VERSION) + " (SuiteSparse " +
                      std::to_string(SUITESPARSE_MAIN_VERSION) + "." + std::to_string(SUITESPARSE_SUB_VERSION) +
                      "." + std::to_string(SUITESPARSE_SUBSUB_VERSION) + ")";
  m.openblas_num_threads_env = env_or_unset("OPENBLAS_NUM_THREADS");
  m.omp_num_threads_env = env_or_unset("OMP_NUM_THREADS");
  m.libblas_alternative = resolved_path("/usr/lib/x86_64-linux-gnu/libblas.so.3");
  m.liblapack_alternative = resolved_path("/usr/lib/x86_64-linux-gnu/liblapack.so.3");

  std::ifstream maps("/proc/self/maps");
  std::set<std::string> seen;
  std::string line;
  while (std::getline(maps, line)) {
    const auto slash = line.find('/');
    if (slash == std::string::npos) continue;
    const std::string file = line.substr(slash);
    const std::string base = file.substr(file.rfind('/') + 1);
    if (base.find("blas") != std::string::npos && seen.insert(file).second) m.loaded_blas.push_back(file);
  }

  // OpenBLAS answers these when it is the BLAS behind libblas.so.3 (looked up, not linked, so the
  // benchmark also runs on the reference BLAS or BLIS).
  using IntFn = int (*)();
  using StrFn = char* (*)();
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_get_num_threads")) {
    IntFn fn;
    static_assert(sizeof(fn) == sizeof(f), "function and object pointers differ in size");
    std::memcpy(&fn, &f, sizeof(fn));
    m.openblas_threads = fn();
  }
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_get_config")) {
    StrFn fn;
    std::memcpy(&fn, &f, sizeof(fn));
    if (const char* s = fn()) m.openblas_config = s;
  }
  return m;
}

void print_machine_info(std::ostream& os, const MachineInfo& m) {
  os << "# machine: " << m.affinity_cpus << " CPUs usable (nproc), " << m.online_cpus << " online; "
     << m.cpu_model << "; " << std::fixed << std::setprecision(1) << m.mem_total_gib << " GiB RAM; "
     << m.kernel << "\n";
  os.unsetf(std::ios::floatfield);
  os << "# build: " << m.compiler << (m.assertions ? ", ASSERTIONS ON (not a Release build)" : ", NDEBUG")
     << "; Eigen " << m.eigen_version << "; CHOLMOD " << m.cholmod_version << "\n";
  os << "# BLAS: OPENBLAS_NUM_THREADS=" << m.openblas_num_threads_env
     << ", OMP_NUM_THREADS=" << m.omp_num_threads_env << "\n";
  os << "# BLAS: libblas.so.3 -> " << m.libblas_alternative << ", liblapack.so.3 -> "
     << m.liblapack_alternative << "\n";
  os << "# BLAS: loaded:";
  if (m.loaded_blas.empty()) os << " (none found in /proc/self/maps)";
  for (const auto& f : m.loaded_blas) os << " " << f;
  os << "\n";
  if (m.openblas_threads >= 0)
    os << "# BLAS: OpenBLAS threads " << m.openblas_threads << ", config \"" << m.openblas_config << "\"\n";
  if (const std::string note = symcontact::blas_kernel_note(); !note.empty()) os << "# BLAS: " << note << "\n";
}

double peak_rss_mib() { return status_mib("VmHWM"); }
double current_rss_mib() { return status_mib("VmRSS"); }

bool reset_peak_rss() {
  malloc_trim(0);
  std::ofstream f("/proc/self/clear_refs");
  if (!f) return false;
  f << "5";
  f.close();
  return !f.fail();
}

double process_cpu_seconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double min_time(int repeat, const std::function<void()>& f) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < std::max(1, repeat); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
    best = std::min(best, dt.count());
  }
  return best;
}

std::vector<double> size_ladder(double min_size, double max_size) {
  std::vector<double> sizes;
  for (double decade = 1e4; decade <= 1e9; decade *= 10)
    for (const double s : {decade, 3 * decade})
      if (s >= min_size && s <= max_size) sizes.push_back(s);
  return sizes;
}

ResultTable::ResultTable(std::vector<Column> columns, std::ostream& out, bool markdown)
    : columns_(std::move(columns)), out_(out), markdown_(markdown) {
  for (const auto& c : columns_) {
    int w = static_cast<int>(c.header.size());
    switch (c.kind) {
      case Kind::kInteger: w = std::max(w, 9); break;
      case Kind::kFixed: w = std::max(w, 6 + c.precision); break;
      case Kind::kScientific: w = std::max(w, 6 + c.precision); break;
      case Kind::kText: w = std::max(w, 4); break;
    }
    widths_.push_back(w);
  }
}

void ResultTable::write_csv(const std::string& path, bool append) {
  csv_.open(path, append ? std::ios::app : std::ios::trunc);
  if (!csv_) throw std::runtime_error("cannot open CSV file '" + path + "' for writing");
  if (append) return;
  for (std::size_t k = 0; k < columns_.size(); ++k) csv_ << (k ? "," : "") << columns_[k].key;
  csv_ << "\n" << std::flush;
}

void ResultTable::print_header() {
  if (header_printed_) return;
  header_printed_ = true;
  std::ostringstream line, rule;
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    if (columns_[k].header.empty()) continue;
    if (markdown_) {
      line << "| " << columns_[k].header << " ";
      rule << "|" << std::string(columns_[k].header.size() + 1, '-') << ":";
    } else {
      line << std::setw(widths_[k] + 2) << columns_[k].header;
      rule << std::string(2, ' ') << std::string(widths_[k], '-');
    }
  }
  if (markdown_) {
    line << "|";
    rule << "|";
  }
  out_ << line.str() << "\n" << rule.str() << "\n" << std::flush;
}

std::string ResultTable::format(const Column& c, const Value& v) const {
  if (v.is_text) return v.text;
  if (!std::isfinite(v.number)) return "-";
  std::ostringstream s;
  switch (c.kind) {
    case Kind::kInteger: s << static_cast<long long>(std::llround(v.number)); break;
    case Kind::kFixed: s << std::fixed << std::setprecision(c.precision) << v.number; break;
    case Kind::kScientific: s << std::scientific << std::setprecision(c.precision) << v.number; break;
    case Kind::kText: s << v.number; break;
  }
  return s.str();
}

void ResultTable::add_row(const std::vector<Value>& row) {
  if (row.size() != columns_.size())
    throw std::logic_error("ResultTable::add_row: " + std::to_string(row.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  print_header();
  std::ostringstream line;
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    if (columns_[k].header.empty()) continue;
    const std::string s = format(columns_[k], row[k]);
    if (markdown_)
      line << "| " << s << " ";
    else
      line << std::setw(widths_[k] + 2) << s;
  }
  if (markdown_) line << "|";
  out_ << line.str() << "\n" << std::flush;

  if (csv_.is_open()) {
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      csv_ << (k ? "," : "");
      if (row[k].is_text)
        csv_ << row[k].text;
      else
        csv_ << std::setprecision(17) << row[k].number;  // round-trip: results compared to 1e-9 relative
    }
    csv_ << "\n" << std::flush;
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read '" + path + "'");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < std::min(x.size(), y.size()); ++k) {
    if (!(x[k] > 0 && y[k] > 0)) continue;
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    n += 1;
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double den = n * sxx - sx * sx;
  if (n < 2 || !(den > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / den;
}

void finish_sweep(const std::string& name, std::chrono::steady_clock::time_point start, bool rss_reset_ok,
                  const std::string& measured, const std::string& work_dir, bool keep_work) {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "\n# " << name << " sweep: " << std::fixed << std::setprecision(1) << wall << std::defaultfloat
            << " s wall\n";
  if (!rss_reset_ok)
    std::cout << "# note: /proc/self/clear_refs refused the peak-RSS reset: peak RSS is monotone over the run\n";
  else
    std::cout << "# peak RSS: of " << measured << ", per size (VmHWM reset before each size)\n";
  if (keep_work)
    std::cout << "# wrapper .geo and .toml kept in " << work_dir << "\n";
  else
    std::filesystem::remove_all(work_dir);
}

std::string make_work_dir() {
  std::string templ = (std::filesystem::temp_directory_path() / "symcontact-bench-XXXXXX").string();
  if (!mkdtemp(templ.data())) throw std::runtime_error("cannot create a temporary directory " + templ);
  return templ;
}

}  // namespace symcontact::bench
