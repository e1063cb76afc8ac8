// Progress reporting: pure line formatting plus a reporter that throttles terminal redraws.
#include "cli/progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace mistfall {

namespace {

std::string format(const char* fmt, auto... args) {
  char buf[128];
  const int n = std::snprintf(buf, sizeof(buf), fmt, args...);
  return std::string(buf, static_cast<std::size_t>(std::clamp(n, 0, static_cast<int>(sizeof(buf)) - 1)));
}

double fraction(const ProgressSnapshot& s) {
  if (!(s.end_time > 0.0)) return 1.0;
  return std::clamp(s.sim_time / s.end_time, 0.0, 1.0);
}

// Enough decimals to show the end time with at least three significant digits (4 minimum).
int timeDecimals(double end_time) {
  if (!(end_time > 0.0) || end_time >= 0.1) return 4;
  return std::min(9, 2 + static_cast<int>(std::ceil(-std::log10(end_time))));
}

std::string timeText(const ProgressSnapshot& s) {
  if (s.count_unit)
    return format("%lld/%lld %s", std::llround(s.sim_time), std::llround(s.end_time), s.count_unit);
  const int d = timeDecimals(s.end_time);
  return format("t=%.*f/%.*f s", d, s.sim_time, d, s.end_time);
}

std::string rateText(double steps_per_second, const char* unit = "steps") {
  if (!std::isfinite(steps_per_second)) return format("-- %s/s", unit);
  if (steps_per_second >= 100.0) return format("%.0f %s/s", steps_per_second, unit);
  return format("%.1f %s/s", steps_per_second, unit);
}

std::string rateText(const ProgressSnapshot& s) {
  return rateText(s.steps_per_second, s.count_unit ? s.count_unit : "steps");
}

// ", step 12" / "  step 12  dt=1.0e-04 s" between the time and the rate; nothing when counting items.
std::string stepText(const ProgressSnapshot& s, bool with_dt) {
  if (s.count_unit) return with_dt ? "  " : ", ";
  if (with_dt) return format("  step %lld  dt=%.1e s  ", static_cast<long long>(s.step), s.dt);
  return format(", step %lld, ", static_cast<long long>(s.step));
}

double steadySeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0 || seconds > 1e9) return "--:--";
  const auto total = static_cast<long long>(std::llround(seconds));
  const long long h = total / 3600, m = (total / 60) % 60, sec = total % 60;
  if (h > 0) return format("%lld:%02lld:%02lld", h, m, sec);
  return format("%lld:%02lld", m, sec);
}

std::string formatTerminalLine(const ProgressSnapshot& s) {
  const double f = fraction(s);
  const std::string rest = format("  %5.1f%%  ", 100.0 * f) + timeText(s) + stepText(s, true) + rateText(s) +
                           "  ETA " + formatDuration(s.eta_seconds);
  constexpr int kMaxColumns = 99;
  const int width = std::clamp(kMaxColumns - 2 - static_cast<int>(rest.size()), 10, 20);
  const int filled = std::clamp(static_cast<int>(std::lround(f * width)), 0, width);
  std::string line;
  line.reserve(static_cast<std::size_t>(width) + 2 + rest.size());
  line.push_back('[');
  line.append(static_cast<std::size_t>(filled), '#');
  line.append(static_cast<std::size_t>(width - filled), '.');
  line.push_back(']');
  line += rest;
  if (line.size() > static_cast<std::size_t>(kMaxColumns)) line.resize(kMaxColumns);
  return line;
}

std::string formatPlainLine(const ProgressSnapshot& s) {
  return "progress: " + timeText(s) + format(" (%.0f%%)", 100.0 * fraction(s)) + stepText(s, false) + rateText(s) +
         ", ETA " + formatDuration(s.eta_seconds);
}

ProgressReporter::ProgressReporter(double end_time, double start_time, std::ostream& out, ProgressMode mode,
                                   ProgressClock clock)
    : end_time_(end_time),
      start_time_(start_time),
      out_(out),
      terminal_(mode == ProgressMode::Terminal ||
                (mode == ProgressMode::Auto && &out == &std::cerr && ::isatty(::fileno(stderr)) == 1)),
      clock_(clock ? std::move(clock) : ProgressClock(&steadySeconds)),
      t0_(clock_()),
      sim_time_(start_time) {
  const double f = end_time > 0.0 ? start_time / end_time : 1.0;
  next_decile_ = static_cast<int>(std::floor(f * 10.0 + 1e-9)) + 1;
  last_line_ = t0_;
}

ProgressSnapshot ProgressReporter::snapshot(double now) const {
  ProgressSnapshot s;
  s.sim_time = sim_time_;
  s.end_time = end_time_;
  s.step = step_;
  s.dt = dt_;
  s.count_unit = count_unit_;
  s.elapsed_seconds = now - t0_;
  if (have_update_ && s.elapsed_seconds > 0.0) {
    s.steps_per_second = static_cast<double>(step_ - first_step_ + 1) / s.elapsed_seconds;
    const double sim_rate = (sim_time_ - start_time_) / s.elapsed_seconds;
    if (sim_rate > 0.0) s.eta_seconds = std::max(0.0, end_time_ - sim_time_) / sim_rate;
  }
  return s;
}

void ProgressReporter::draw(const ProgressSnapshot& s) {
  const std::string line = formatTerminalLine(s);
  out_ << '\r' << line;
  if (line.size() < last_len_) out_ << std::string(last_len_ - line.size(), ' ');
  out_.flush();
  last_len_ = line.size();
  drawn_ = true;
}

void ProgressReporter::clearBar() {
  if (!drawn_) return;
  out_ << '\r' << std::string(last_len_, ' ') << '\r';
  last_len_ = 0;
  drawn_ = false;
}

void ProgressReporter::update(double sim_time, std::int64_t step, double dt) {
  if (finished_) return;
  if (!have_update_) {
    first_step_ = step;
    have_update_ = true;
  }
  sim_time_ = sim_time;
  step_ = step;
  dt_ = dt;
  const double now = clock_();
  if (terminal_) {
    if (!drawn_ || now - last_draw_ >= 0.1) {
      last_draw_ = now;
      draw(snapshot(now));
    }
    return;
  }
  const double f = end_time_ > 0.0 ? sim_time / end_time_ : 1.0;
  const bool mark = f * 10.0 + 1e-9 >= next_decile_;
  if (mark || now - last_line_ >= kPlainLineGapSeconds) {
    if (mark) next_decile_ = static_cast<int>(std::floor(f * 10.0 + 1e-9)) + 1;
    last_line_ = now;
    out_ << formatPlainLine(snapshot(now)) << '\n';
    out_.flush();
  }
}

void ProgressReporter::log(const std::string& line) {
  const bool redraw = terminal_ && drawn_ && !finished_;
  clearBar();
  out_ << line << '\n';
  if (redraw) draw(snapshot(clock_()));
  out_.flush();
}

void ProgressReporter::finish() {
  if (finished_) return;
  const ProgressSnapshot s = snapshot(clock_());
  if (terminal_) {
    draw(s);
    out_ << '\n';
    drawn_ = false;
    last_len_ = 0;
  } else {
    out_ << "progress: done, " << timeText(s) << stepText(s, false) << rateText(s) << ", wall "
         << formatDuration(s.elapsed_seconds) << '\n';
  }
  out_.flush();
  finished_ = true;
}

}  // namespace mistfall
