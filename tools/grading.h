// tools/grading.h — judging lab renders against reference_images/: the one
// implementation behind labgrade (instructors), labrun (make references) and
// the calibration tests.
//
// A view is graded from the references, not from the submission: every
// reference_images/<lab>__<view>.png is one view to grade, and a submission
// that has no render for it fails that view ("no render"), as does a render
// that crashes, exits with an error, takes too long or has the wrong size.
// Nothing is skipped silently.
//
// The metric (compare.h, calibrated in tests/grading/): a pixel differs when
// a channel is off by more than the MANIFEST's channel threshold; a differing
// pixel is excused when a shift of up to the shift radius explains it (a line
// drawn one pixel over); the view passes when the unexcused share of pixels is
// at most the MANIFEST's max_differing_share.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"

namespace gllab::grading {

/// Bad command line or unusable input (no references, no MANIFEST): exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// reference_images/MANIFEST: "key: value" lines (# comments).
struct Manifest {
  std::map<std::string, std::string> fields;
  Tolerance tolerance;
};
/// Throws UsageError naming the file and the missing or malformed key.
Manifest read_manifest(const std::filesystem::path& refs);

/// One view: reference_images/<lab>__<view>.png.
struct ViewId {
  std::string lab, view;
  std::string name() const { return lab + "__" + view; }
  bool operator<(const ViewId& o) const { return name() < o.name(); }
  bool operator==(const ViewId& o) const { return lab == o.lab && view == o.view; }
};

/// Every reference PNG in refs, sorted by name. Throws UsageError when
/// there is none or a name is not <lab>__<view>.png.
std::vector<ViewId> reference_views(const std::filesystem::path& refs);

/// Keeps the views whose lab matches one of `labs` ("13" or "15_bspline_curves")
/// and whose view is in `views` (empty: all). Throws UsageError for a lab or
/// view that matches nothing, naming it and what exists.
std::vector<ViewId> select_views(const std::vector<ViewId>& all, const std::vector<std::string>& labs,
                                 const std::vector<std::string>& views);

/// Where a submission's renders come from.
/// One render, or why there is none.
struct Obtained {
  std::optional<Image> image;
  std::string error;  // set when image is empty
};

class Source {
 public:
  virtual ~Source() = default;
  /// The submission's image of the view. Throws SubmissionError with the
  /// reason when there is none (no renderer, crash, GL error, timeout, ...).
  virtual Image obtain(const ViewId& id) const = 0;
  /// Several views of ONE lab at once, in order. The default asks obtain()
  /// for each; a build renders them in one process (much faster: one
  /// program start and one llvmpipe shader cache for the lab).
  virtual std::vector<Obtained> obtain_batch(const std::vector<ViewId>& views) const;
  /// What to call this submission in messages and reports.
  virtual std::string describe() const = 0;
};

struct SubmissionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// How long one render may take before it counts as hung (a student's endless loop).
inline constexpr double kDefaultTimeoutSeconds = 60;

/// A build of this repository: renders each view with <dir>/<lab>_headless
/// (or <dir>/bin/<lab>_headless) --view V --out - (a raw frame, image/pam.h).
/// env entries NAME=VALUE go to the renderer (e.g. GALLIUM_DRIVER=softpipe).
/// A render that runs longer than timeout_seconds is killed and fails.
std::unique_ptr<Source> build_source(const std::filesystem::path& dir, std::vector<std::string> env = {},
                                     double timeout_seconds = kDefaultTimeoutSeconds);
/// A folder of PNGs named <lab>__<view>.png.
std::unique_ptr<Source> image_source(const std::filesystem::path& dir);
/// Is dir a build (has headless programs) rather than a folder of images?
bool looks_like_build(const std::filesystem::path& dir);

struct ViewResult {
  ViewId id;
  bool passed = false;
  std::string reason;                // why it failed; empty when it passed
  std::optional<Comparison> comparison;  // when a render and the reference were compared
  double seconds = 0;                // obtaining the render plus the comparison
  std::optional<Image> submission;   // kept when asked for (reports, failures)
};

/// The metric the view is judged by: the unexcused share of pixels.
inline double metric(const Comparison& c) { return c.mismatched_share(); }

/// Grades one view: obtains the render, compares it with the reference
/// (already read), keeps the submission image when keep_image or when it
/// failed a comparison. Never throws for a bad submission.
ViewResult grade_view(const Source& source, const ViewId& id, const Image& reference, const Tolerance& tolerance,
                      bool keep_image);

struct Grade {
  std::string submission;  // Source::describe()
  std::vector<ViewResult> views;
  int passed() const;
  /// Percent of views passed, 0..100.
  double score() const;
  /// Per lab: views passed and views graded.
  std::map<std::string, std::pair<int, int>> by_lab() const;
};

/// What grade() reports while it runs: a view starts (finished == nullptr)
/// or ends. Calls come from several threads, one at a time.
struct ProgressEvent {
  int done = 0, total = 0;              // views finished so far, views in all
  const ViewId* view = nullptr;         // the view starting or ending
  const ViewResult* finished = nullptr; // its result when it ended
};
using Progress = std::function<void(const ProgressEvent&)>;

/// Grades the views with `jobs` threads (>= 1), in the views' order in the
/// result. References are read once, here. A lab's views are obtained as
/// one batch; a view that fails from the batch is rendered again on its own
/// and graded from that render, so a verdict never depends on which views
/// a process drew before (references are rendered one view per process).
Grade grade(const Source& source, const std::vector<ViewId>& views, const std::filesystem::path& refs,
            const Tolerance& tolerance, int jobs, bool keep_images, const Progress& progress = nullptr);

}  // namespace gllab::grading
