#pragma once
/// \file bench_support.hpp
/// Shared pieces of the symcontact benchmarks: a description of the machine and of the BLAS in use,
/// peak memory from /proc, min-of-repeats timing, problem-size ladders, and a result table printed
/// row by row (as each size finishes) to the terminal and to a CSV file.
///
/// Nothing here knows about elasticity or contact; the elasticity and contact benchmarks both
/// use it so that their outputs look alike.

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace symcontact::bench {

/// What the run depends on: printed at the top of every benchmark output.
struct MachineInfo {
  int online_cpus = 0;    ///< sysconf(_SC_NPROCESSORS_ONLN)
  int affinity_cpus = 0;  ///< CPUs this process may run on (what `nproc` prints)
  std::string cpu_model;  ///< first "model name" of /proc/cpuinfo
  double mem_total_gib = 0.0;
  std::string kernel;     ///< uname -sr
  std::string compiler;   ///< __VERSION__ of the compiler that built the benchmark
  bool assertions = false;  ///< NDEBUG not defined (a Debug build: timings not meaningful)
  std::string eigen_version, cholmod_version;
  std::string openblas_num_threads_env;  ///< OPENBLAS_NUM_THREADS, or "(unset)"
  std::string omp_num_threads_env;       ///< OMP_NUM_THREADS, or "(unset)"
  std::string libblas_alternative;       ///< readlink -f /usr/lib/x86_64-linux-gnu/libblas.so.3
  std::string liblapack_alternative;     ///< readlink -f /usr/lib/x86_64-linux-gnu/liblapack.so.3
  std::vector<std::string> loaded_blas;  ///< mapped files whose name contains "blas" (/proc/self/maps)
  int openblas_threads = -1;             ///< openblas_get_num_threads() when OpenBLAS is loaded, else −1
  std::string openblas_config;           ///< openblas_get_config() when OpenBLAS is loaded
};

MachineInfo machine_info();
/// Lines of the form "# key: value" (so a CSV reader that skips '#' lines can keep them).
void print_machine_info(std::ostream& os, const MachineInfo& m);

/// Peak resident set size of this process in MiB (VmHWM of /proc/self/status); −1 if unavailable.
/// The peak is monotone over the process unless reset_peak_rss() succeeded in between.
double peak_rss_mib();
/// Current resident set size in MiB (VmRSS); −1 if unavailable.
double current_rss_mib();
/// Resets VmHWM to the current RSS by writing "5" to /proc/self/clear_refs (Linux ≥ 4.0), after handing the
/// heap's free memory back to the system (glibc's malloc_trim): without it the RSS an earlier measurement freed
/// but the heap kept counts in the next peak, by as much as the whole earlier peak.
/// Returns false when the kernel refused; peak_rss_mib() is then a peak over the whole process.
bool reset_peak_rss();

/// CPU time of this process (all threads, user + system) in seconds: CLOCK_PROCESS_CPUTIME_ID.
/// Differences of it are less sensitive than wall time to other processes sharing the cores.
double process_cpu_seconds();

/// Calls f() `repeat` times (at least once) and returns the smallest wall-clock time in seconds.
double min_time(int repeat, const std::function<void()>& f);

/// The sizes 1e4, 3e4, 1e5, 3e5, 1e6, 3e6, ... (a roughly geometric ladder, ×√10 per step) that lie
/// in [min_size, max_size].
std::vector<double> size_ladder(double min_size, double max_size);

/// Least-squares slope of log y against log x over the pairs with x > 0 and y > 0: the exponent α of
/// y ∝ x^α. NaN with fewer than two such pairs or when every x is the same.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

/// The whole text of a file; throws std::runtime_error naming it when it cannot be read.
std::string read_file(const std::string& path);
/// Writes `text` to a file; throws std::runtime_error naming it when it cannot be written.
void write_file(const std::string& path, const std::string& text);

/// The closing lines of a sweep over sizes: its wall time since `start`, what the peak RSS column
/// measured (`measured`, e.g. "meshing + setup + the contact solves") or that its reset was refused, and
/// the work directory, kept (its path printed) or removed.
void finish_sweep(const std::string& name, std::chrono::steady_clock::time_point start, bool rss_reset_ok,
                  const std::string& measured, const std::string& work_dir, bool keep_work);

/// A fresh directory under the system temporary directory (symcontact-bench-XXXXXX); throws
/// std::runtime_error when it cannot be made.
std::string make_work_dir();

/// A result table with a fixed set of columns. Rows are printed as soon as they are added, so a long
/// sweep shows its progress; the same rows go, at full precision, to an optional CSV file.
class ResultTable {
 public:
  enum class Kind { kInteger, kFixed, kScientific, kText };
  struct Column {
    std::string key;     ///< CSV header (snake_case, with the unit as suffix: "factorize_s")
    std::string header;  ///< terminal header ("factor [s]"); empty: CSV only
    Kind kind = Kind::kFixed;
    int precision = 3;   ///< digits after the point (kFixed) or significant digits − 1 (kScientific)
  };
  /// One cell: a number, or a text for kText columns.
  struct Value {
    Value(double v) : number(v) {}                   // NOLINT: implicit on purpose (row literals)
    Value(const char* s) : text(s), is_text(true) {}  // NOLINT
    Value(std::string s) : text(std::move(s)), is_text(true) {}  // NOLINT
    double number = 0.0;
    std::string text;
    bool is_text = false;
  };

  /// `markdown`: print "| a | b |" rows (for docs/performance.md) instead of aligned columns.
  ResultTable(std::vector<Column> columns, std::ostream& out, bool markdown);
  /// Opens (truncates) a CSV file and writes its header; throws std::runtime_error on failure.
  /// Several tables may share one file if they have the same columns: pass append = true.
  void write_csv(const std::string& path, bool append = false);
  /// Prints the header (once); add_row() does it when needed.
  void print_header();
  /// Adds one row (one Value per column, in column order), prints it and appends it to the CSV.
  void add_row(const std::vector<Value>& row);

 private:
  std::string format(const Column& c, const Value& v) const;
  std::vector<Column> columns_;
  std::vector<int> widths_;
  std::ostream& out_;
  bool markdown_;
  bool header_printed_ = false;
  std::ofstream csv_;
};

}  // namespace symcontact::bench
