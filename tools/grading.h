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
// Two profiles, each with its own limits in the MANIFEST (calibrated in
// tests/grading/, stated in README.md "Grading"):
//   build   labgrade renders a student's build with the reference renderer;
//           benign variation is correct code computing the same thing another
//           way, so the limits are tight;
//   images  renders made elsewhere (softpipe, other llvmpipe settings, a
//           window); the limits allow a foreign renderer's lighting and lines.
// In both, a pixel differs when a channel is off by more than the profile's
// channel threshold; a differing pixel is excused when a shift of up to the
// shift radius explains it on a thin feature (a line or edge moved, not a
// surface's colour changed); the view passes when both the unexcused and the
// excused share stay within the profile's limits (compare.h, score()).
//
// The text a view draws is graded too: reference_images/<lab>__<view>.txt
// holds its --print-text lines; words must match exactly, numbers within the
// MANIFEST's relative tolerance. An error view (it must refuse to draw) has
// reference_images/<lab>__<view>.error, the one line it must exit 1 with;
// a build is graded on it, a folder of images cannot be.
//
// The instructor's files are checked before any grading: every reference the
// views use must be a regular file that decodes, of the MANIFEST's size, and
// every MANIFEST field must be in its range; a fault is a UsageError naming
// the file or the field and its value (exit 2), never a student's failing row.
//
// Limits (tools/README.md lists them), each far above any real use:
//   kMaxJobs                 256 renders at once (a 2-core machine uses 2)
//   kMaxTimeoutSeconds       3600 s for one render (one takes well under 1 s)
//   kMaxRendererOutputBytes  64 MiB of stdout or of stderr per renderer run (process.h)
//   kMaxImageFileBytes       16 MiB per PNG file (the largest reference: 129 KB)
//   kMaxImageSide            4096 pixels wide or high (every view: 512x512)
//   kMaxTextFileBytes        1 MiB per text file: MANIFEST, <view>.txt, .error, a
//                            renderer's --text-out (the largest: 1,830 bytes)
#pragma once

#include <cstdint>
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
#include "process.h"

namespace gllab::grading {

/// --jobs: at most this many renders at once.
inline constexpr int kMaxJobs = 256;
/// --timeout: at most this many seconds for one render (an hour).
inline constexpr double kMaxTimeoutSeconds = 3600;
/// A PNG read (a reference, or a render in a folder of images): at most 16 MiB.
inline constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t{16} << 20;
/// An image read or compared: at most this many pixels wide and high.
inline constexpr int kMaxImageSide = 4096;
/// A text file read (MANIFEST, <view>.txt, <view>.error, --text-out): at most 1 MiB.
inline constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t{1} << 20;
using gllab::kMaxRendererOutputBytes;

/// Strict numbers (command-line options, MANIFEST values): the whole text is
/// the number, in decimal (no spaces, no hex, no inf or nan), within [lo, hi];
/// an integer has digits only (an optional '-'), so "3.5" and "1e2" are not
/// integers. std::nullopt when the text is not such a number.
std::optional<double> parse_number(const std::string& text, double lo, double hi);
std::optional<long long> parse_integer(const std::string& text, long long lo, long long hi);

/// Bad command line or unusable input (no references, no MANIFEST): exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Profile { kBuild, kImages };
const char* profile_name(Profile p);
/// "build" or "images"; throws UsageError for anything else.
Profile parse_profile(const std::string& name);

/// reference_images/MANIFEST: "key: value" lines (# comments).
struct Manifest {
  std::map<std::string, std::string> fields;
  Tolerance build, images;        // <profile>_channel_threshold, ..._max_shifted_share
  double text_relative = 0;       // text_relative_tolerance: |a - b| <= this * max(|a|, |b|)
  double text_absolute = 0;       // text_absolute_tolerance: and numbers this small are equal
  int width = 0, height = 0;      // size: WIDTHxHEIGHT of every reference (0: not given)
  const Tolerance& tolerance(Profile p) const { return p == Profile::kBuild ? build : images; }
};
/// Reads refs/MANIFEST (a regular file of at most kMaxTextFileBytes) with
/// parse_manifest. Throws UsageError naming the file.
Manifest read_manifest(const std::filesystem::path& refs);
/// A MANIFEST's text; `name` names it in errors. Every line is empty, a
/// # comment or "key: value", each key once. Required, with their ranges:
/// <profile>_channel_threshold and _edge_contrast integers 0..255,
/// _shift_radius an integer 0..kMaxShiftRadius, _max_unexcused_share and
/// _max_shifted_share numbers 0..1, text_relative_tolerance and
/// text_absolute_tolerance numbers 0..1; optional: size WIDTHxHEIGHT, each
/// 1..kMaxImageSide. Throws UsageError with one line naming the field and its
/// value: "reference_images/MANIFEST: build_max_shifted_share 'nan' is not a
/// number from 0 to 1".
Manifest parse_manifest(const std::string& text, const std::string& name);

/// One view: reference_images/<lab>__<view>.png, or <lab>__<view>.error for
/// an error view.
struct ViewId {
  std::string lab, view;
  bool error_view = false;
  std::string name() const { return lab + "__" + view; }
  bool operator<(const ViewId& o) const { return name() < o.name(); }
  bool operator==(const ViewId& o) const { return lab == o.lab && view == o.view; }
};

/// Every reference PNG and .error file in refs, sorted by name. Throws
/// UsageError when there is none or a name is not <lab>__<view>.png/.error.
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
  std::optional<std::vector<std::string>> text;  // the lines the view drew, when the source has them
  int exit_status = 0;  // a build's renderer: how it exited (error views pass on 1)

  static Obtained drawn(Image image) {
    Obtained o;
    o.image = std::move(image);
    return o;
  }
  static Obtained failed(std::string why, int exit_status = 0) {
    Obtained o;
    o.error = std::move(why);
    o.exit_status = exit_status;
    return o;
  }
};

/// The first difference between a view's text and its reference, as one
/// line ("line 3: \"n = 12\", the reference \"n = 13\""), or "" when they
/// agree: the same number of lines, the same words and spacing, and each
/// number within relative (or, for numbers both under absolute, any).
std::string text_difference(const std::vector<std::string>& reference, const std::vector<std::string>& got,
                            double relative, double absolute);

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

/// Runs one renderer (argv[0] is its path) with extra environment and limits,
/// and returns how it went. The default is run_process, here; a class grade
/// runs student programs in the sandbox (sandbox.h) instead.
using Launcher = std::function<ProcessResult(const std::vector<std::string>& argv,
                                             const std::vector<std::string>& env,
                                             const ProcessLimits& limits)>;

/// How a build's programs are run.
struct RenderSettings {
  std::vector<std::string> env;  // NAME=VALUE for the renderer (e.g. GALLIUM_DRIVER=softpipe)
  double timeout_seconds = kDefaultTimeoutSeconds;
  /// --set values per lab, given to every render of its views (hidden inputs).
  std::map<std::string, std::vector<std::string>> sets;
  Launcher launch;                   // empty: run_process
  /// Where the renderer's --text-out file is made (empty: the temporary
  /// folder); a launcher must let the renderer write there.
  std::filesystem::path scratch;
};

/// A build of this repository: renders each view with <dir>/<lab> (or
/// <dir>/bin/<lab>) --headless --view V --out - (a raw frame, image/pam.h).
/// A render that runs longer than the timeout (0 < t <= kMaxTimeoutSeconds,
/// else UsageError), or writes more than kMaxRendererOutputBytes to stdout or
/// stderr, is killed and fails.
std::unique_ptr<Source> build_source(const std::filesystem::path& dir, RenderSettings settings);
std::unique_ptr<Source> build_source(const std::filesystem::path& dir, std::vector<std::string> env = {},
                                     double timeout_seconds = kDefaultTimeoutSeconds);
/// A folder of PNGs named <lab>__<view>.png, each with its text <lab>__<view>.txt.
/// A PNG or text that is not a regular file (a FIFO, a device), is larger than
/// kMaxImageFileBytes or kMaxTextFileBytes or wider or higher than
/// kMaxImageSide fails its view with the reason; nothing is waited on.
std::unique_ptr<Source> image_source(const std::filesystem::path& dir);
/// Is dir a build (has lab programs, NN_topic) rather than a folder of images?
bool looks_like_build(const std::filesystem::path& dir);

struct ViewResult {
  ViewId id;
  bool passed = false;
  std::string reason;                // why it failed; empty when it passed
  std::optional<Comparison> comparison;  // when a render and the reference were compared
  double score = 0;                  // comparison->score(tolerance): <= 1 passes (0 without one)
  std::string text_reason;           // the text's first difference, when it differs
  double seconds = 0;                // obtaining the render plus the comparison
  std::optional<Image> submission;   // kept when asked for (reports, failures)
};

/// What a view is judged against: its reference image (none for an error
/// view), its text (when the reference has a .txt), its error line.
struct Reference {
  Image image;
  std::optional<std::vector<std::string>> text;
  std::string error_line;  // an error view's expected first line of stderr
};
/// Reads refs/<view>.png (or .error) and refs/<view>.txt: regular files within
/// kMaxImageFileBytes and kMaxTextFileBytes, a PNG that decodes, an error line
/// that is not empty. Throws UsageError naming the file and what is wrong.
Reference read_reference(const std::filesystem::path& refs, const ViewId& id);

/// Every view's reference, by ViewId::name().
using References = std::map<std::string, Reference>;
/// Reads and checks the references of all the views before any grading
/// (read_reference), and their size: the MANIFEST's size when it gives one,
/// else the size most of them have. Throws UsageError naming the first
/// reference that is missing, unreadable, corrupt or of another size.
References read_references(const std::filesystem::path& refs, const std::vector<ViewId>& views,
                           const Manifest* manifest = nullptr);

/// How a grade judges: the profile's tolerance and the text tolerance.
struct Judgement {
  Profile profile = Profile::kBuild;
  Tolerance tolerance;
  double text_relative = 0, text_absolute = 0;
};
Judgement judgement(const Manifest& m, Profile p);

/// Grades one view: obtains the render, compares it with the reference,
/// keeps the submission image when keep_image or when it failed a
/// comparison. Never throws for a bad submission.
ViewResult grade_view(const Source& source, const ViewId& id, const Reference& reference, const Judgement& judge,
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

/// Grades the views with up to `jobs` threads (clamped to 1..kMaxJobs and to
/// the number of labs), in the views' order in the result. A thread that
/// cannot start leaves the work to those that did (at least this one). A
/// lab's views are obtained as one batch; a view that fails from the batch is
/// rendered again on its own and graded from that render, so a verdict never
/// depends on which views a process drew before (references are rendered one
/// view per process). Every view must have its reference in `references`.
/// Throws (after every thread has stopped) when the grading itself cannot go
/// on, e.g. no temporary file for a renderer's text.
Grade grade(const Source& source, const std::vector<ViewId>& views, const References& references,
            const Judgement& judge, int jobs, bool keep_images, const Progress& progress = nullptr);
/// The same, reading the references first (read_references).
Grade grade(const Source& source, const std::vector<ViewId>& views, const std::filesystem::path& refs,
            const Judgement& judge, int jobs, bool keep_images, const Progress& progress = nullptr);

}  // namespace gllab::grading
