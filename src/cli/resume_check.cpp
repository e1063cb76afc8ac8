// Checks of a run directory before a resume (see resume_check.hpp).
#include "cli/resume_check.hpp"

#include <cmath>
#include <sstream>

#include "case/case_fingerprint.hpp"
#include "io/errors.hpp"
#include "io/pvd_collection.hpp"
#include "io/vtk_writer.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

}  // namespace

template <int D>
std::vector<std::string> checkResume(const fs::path& run, const SimulationState<D>& state,
                                     const std::string& checkpoint_fingerprint, const std::string& case_fingerprint,
                                     std::string* accepted) {
  std::vector<std::string> notes;
  const fs::path checkpoint = run / "checkpoint.bin";
  if (checkpoint_fingerprint.empty()) {
    notes.push_back(checkpoint.string() + " was written by an older mistfall and carries no case fingerprint: "
                    "whether case.toml changed since is not checked");
  } else {
    std::string refused, harmless;
    bool interval_changed = false;
    for (const CaseChange& c : compareFingerprints(checkpoint_fingerprint, case_fingerprint)) {
      (c.harmless ? harmless : refused) += "\n  " + describe(c);
      interval_changed = interval_changed || c.key == "output.interval";
    }
    // The frames are numbered by the output interval (frame k at t = k interval), so a resume cannot change it:
    // the next frame's number would lie in the past (a resume with a finer interval had stepped nowhere, forever).
    if (interval_changed && accepted)
      throw InputError("cannot resume " + run.string() + " with --accept-case-change: output.interval changed, and "
                       "the frames are numbered by it (frame k at t = k interval); keep the checkpoint's interval, "
                       "or start the edited case anew with --overwrite" + refused);
    if (!refused.empty() && accepted) {
      *accepted = refused;
      notes.push_back("case.toml changed since the checkpoint in keys that change the simulation, accepted by "
                      "--accept-case-change: from t = " + number(state.time) + " s on the run is another case "
                      "(recorded in " + (run / "case_changes.txt").string() + "):" + refused);
    } else if (!refused.empty())
      throw InputError("cannot resume " + run.string() + ": its checkpoint was written for another case: " +
                       (run / "case.toml").string() + " differs in what changes the simulation:" + refused +
                       "\n(a checkpoint from another run, or case.toml edited; to run the edited case, start it "
                       "anew with --overwrite)");
    if (!harmless.empty())
      notes.push_back("case.toml changed since the checkpoint in keys that do not change the simulation; they apply "
                      "from t = " + number(state.time) + " s on (`mistfall classify`, `texture --overwrite` and "
                      "`render` redo the later stages for the whole run):" + harmless);
  }

  // The frames the run lists must end at the checkpoint: one per output time up to it.
  PvdCollection pvd(run / "frames.pvd");
  if (!fs::exists(pvd.path())) throw InputError("cannot resume " + run.string() + ": " + pvd.path().string() +
                                                " does not exist");
  pvd.load();
  pvd.truncateAfter(state.time);
  const auto& entries = pvd.entries();
  const std::string from = "cannot resume " + run.string() + ": the checkpoint (t = " + number(state.time) +
                           " s, " + std::to_string(state.next_frame) + " frames written) does not match " +
                           pvd.path().string() + ": ";
  if (static_cast<int>(entries.size()) != state.next_frame)
    throw InputError(from + "it lists " + std::to_string(entries.size()) + " frames up to that time");
  if (entries.empty() || std::abs(entries.back().time - state.time) > 1e-12)
    throw InputError(from + "its last frame is at t = " + (entries.empty() ? "(none)" : number(entries.back().time)) +
                     " s");
  const fs::path last = run / entries.back().file;
  const std::size_t count = readVtp<D>(last).size();
  if (count != state.particles.size())
    throw InputError(from + "its last frame " + last.string() + " holds " + std::to_string(count) +
                     " particles, the checkpoint " + std::to_string(state.particles.size()));
  return notes;
}

template std::vector<std::string> checkResume<2>(const fs::path&, const SimulationState<2>&, const std::string&,
                                                 const std::string&, std::string*);
template std::vector<std::string> checkResume<3>(const fs::path&, const SimulationState<3>&, const std::string&,
                                                 const std::string&, std::string*);

}  // namespace mistfall
