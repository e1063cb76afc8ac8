// Progress reporting on stderr: a redrawn bar on a terminal; otherwise one log line per 10% of simulated time, and
// one whenever kPlainLineGapSeconds of wall time have passed since the last (a long run's log shows it is alive).
#pragma once

#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <utility>

namespace mistfall {

enum class ProgressMode { Auto, Terminal, Plain };  // Auto: Terminal iff out is std::cerr and stderr is a tty

using ProgressClock = std::function<double()>;  // monotonic wall-clock seconds (injectable for tests)

inline constexpr double kPlainLineGapSeconds = 120.0;  // plain mode: the longest wall time between two lines

// Everything one progress line shows; NaN rates/ETA mean "not known yet".
struct ProgressSnapshot {
  double sim_time = 0.0, end_time = 0.0;
  std::int64_t step = 0;
  double dt = 0.0;
  double steps_per_second = std::numeric_limits<double>::quiet_NaN();
  double eta_seconds = std::numeric_limits<double>::quiet_NaN();
  double elapsed_seconds = 0.0;
  // Counting items instead of simulated time: sim_time / end_time are item counts shown as "3/10 frames", and
  // steps_per_second is items per second ("frames/s"); step and dt are not shown. Null: simulated time.
  const char* count_unit = nullptr;
};

// Pure formatting helpers.
std::string formatDuration(double seconds);  // "0:07", "12:34", "1:02:03"; "--:--" if unknown/negative/inf
std::string formatTerminalLine(const ProgressSnapshot& s);  // bar line, at most 99 columns, no '\r'
std::string formatPlainLine(const ProgressSnapshot& s);     // "progress: t=.../... s (10%), step ..., ..."

class ProgressReporter {
 public:
  ProgressReporter(double end_time, double start_time, std::ostream& out = std::cerr,
                   ProgressMode mode = ProgressMode::Auto, ProgressClock clock = {});
  // force_plain = true: Plain mode; false: Auto.
  ProgressReporter(double end_time, double start_time, std::ostream& out, bool force_plain, ProgressClock clock = {})
      : ProgressReporter(end_time, start_time, out, force_plain ? ProgressMode::Plain : ProgressMode::Auto,
                         std::move(clock)) {}
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // Counts items (e.g. "frames") instead of simulated time (see ProgressSnapshot::count_unit); report progress with
  // update(done, done, 0). Call before the first update.
  void countIn(const char* unit) { count_unit_ = unit; }
  void update(double sim_time, std::int64_t step, double dt);  // cheap; redraws at most ~10 times/s
  void log(const std::string& line);  // prints a line without garbling the bar
  void finish();                      // final state + newline (terminal) or a summary line (plain); idempotent

  bool terminal() const { return terminal_; }

 private:
  ProgressSnapshot snapshot(double now) const;
  void draw(const ProgressSnapshot& s);
  void clearBar();

  double end_time_, start_time_;
  std::ostream& out_;
  bool terminal_;
  ProgressClock clock_;
  double t0_;                       // wall clock at construction
  double last_draw_ = -1e300;       // wall clock of the last terminal redraw
  bool have_update_ = false, drawn_ = false, finished_ = false;
  std::int64_t first_step_ = 0;     // step of the first update (steps counted from first_step_ - 1)
  double sim_time_ = 0.0, dt_ = 0.0;
  std::int64_t step_ = 0;
  int next_decile_ = 1;             // plain mode: next 10% mark to report
  double last_line_;                // plain mode: wall clock of the last line (construction before the first)
  std::size_t last_len_ = 0;        // length of the bar currently on screen
  const char* count_unit_ = nullptr;
};

}  // namespace mistfall
