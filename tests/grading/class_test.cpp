// tests/grading/class_test.cpp — labgrade --class on a class of source trees:
// a synthetic class of 23 students who hand in the gllab tree, built in the
// sandbox with the class's compiler cache and graded on lab 12 with hidden
// inputs. Most are correct; some carry real mistakes (tests/grading/mistakes),
// one a mistake that only hidden inputs show, one does not compile; six are
// hostile (they read others' files, write outside their tree, open a socket,
// fork without end, fill the disk, never end); one copies the references.
// Every row must be right, and nothing outside the sandbox may change. Then
// examples/grade_class_parallel.sh grades 7 of them again with a warm cache,
// one process per student, and its merged CSV must say the same.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "sandbox.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::run_process;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;
using gllab::testing::ScratchDir;

const std::string kLab = "12_bezier_curves";
const std::string kLabFile = "labs/" + kLab + "/" + kLab + ".cpp";
const std::string kSecret = "SECRET-7f3a9c-of-another-student";

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What a student clones: a copy of the repository's files (a copy, not hard
// links: a sandbox that failed must not reach the repository through them).
void copy_tree(const fs::path& to) {
  fs::create_directories(to);
  for (const auto& e : fs::directory_iterator(kSourceDir)) {
    const std::string name = e.path().filename().string();
    if (name == ".git" || name.rfind("build", 0) == 0 || name == "out" || name == "labgrade-work") continue;
    fs::copy(e.path(), to / name, fs::copy_options::recursive);
  }
}

// Replaces the one occurrence of `find` in the tree's file.
void edit(const fs::path& tree, const std::string& file, const std::string& find, const std::string& replace) {
  std::string text = file_text(tree / file);
  const auto at = text.find(find);
  ASSERT_NE(at, std::string::npos) << find << " not in " << file;
  ASSERT_EQ(text.find(find, at + 1), std::string::npos) << find << " twice in " << file;
  text.replace(at, find.size(), replace);
  std::ofstream(tree / file, std::ios::binary | std::ios::trunc) << text;
}

void apply_mistake(const fs::path& tree, const std::string& name) {
  const nlohmann::json m = nlohmann::json::parse(file_text(kSourceDir / "tests/grading/mistakes" / (name + ".json")));
  edit(tree, m.value("file", kLabFile), m["find"], m["replace"]);
}

// Code run when the lab program starts (its init()).
void hostile_init(const fs::path& tree, const std::string& includes, const std::string& code) {
  edit(tree, kLabFile, "#include <algorithm>\n", "#include <algorithm>\n" + includes);
  edit(tree, kLabFile, "void init() { glClearColor(0.1f, 0.1f, 0.12f, 1.f); }",
       "void init() {\n" + code + "\n  glClearColor(0.1f, 0.1f, 0.12f, 1.f);\n}");
}

// Every regular file under dir with its contents' hash and size.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
    if (!it->is_regular_file() || it->is_symlink()) continue;
    files[fs::relative(it->path(), dir).string()] = std::to_string(std::hash<std::string>{}(file_text(it->path())));
  }
  return files;
}

// The CSV as rows by student: column name -> value.
std::map<std::string, std::map<std::string, std::string>> read_csv(const std::string& text) {
  std::map<std::string, std::map<std::string, std::string>> rows;
  std::istringstream in(text);
  std::string header, line;
  std::getline(in, header);
  const auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : l) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    return cells;
  };
  const std::vector<std::string> names = split(header);
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    for (std::size_t k = 0; k < names.size() && k < cells.size(); ++k) rows[cells[0]][names[k]] = cells[k];
  }
  return rows;
}

// A TCP listener on the host's 127.0.0.1 that counts the connections it accepts.
class Listener {
 public:
  Listener() {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a);
    listen(fd_, 8);
    socklen_t n = sizeof a;
    getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &n);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] {
      while (true) {
        const int c = accept(fd_, nullptr, nullptr);
        if (c < 0 || stop_) break;
        ++accepted_;
        close(c);
      }
    });
  }
  ~Listener() {
    stop_ = true;
    shutdown(fd_, SHUT_RDWR);
    close(fd_);
    thread_.join();
  }
  int port() const { return port_; }
  int accepted() const { return accepted_; }

 private:
  int fd_ = -1, port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<int> accepted_{0};
  std::thread thread_;
};

TEST(LabgradeClass, ASyntheticClassOfSourceTreesIsGradedInTheSandboxWithHiddenInputs) {
  const std::string why = gllab::sandbox_unavailable_reason();
  if (!why.empty()) GTEST_SKIP() << "no sandbox here: " << why;
  ScratchDir dir("class");
  const fs::path klass = dir / "class", work = dir / "work", canary = dir / "instructor" / "canary.txt";
  fs::create_directories(canary.parent_path());
  std::ofstream(canary) << "the instructor's file\n";
  Listener listener;

  std::vector<std::string> correct;
  for (int k = 1; k <= 11; ++k) correct.push_back("correct_" + std::string(k < 10 ? "0" : "") + std::to_string(k));
  for (const std::string& s : correct) copy_tree(klass / s);
  // A file of correct_01 that the others must not see.
  std::ofstream(klass / "correct_01" / "notes.txt") << kSecret << "\n";

  const std::vector<std::string> mistakes = {"de_casteljau_one_minus_t", "control_point_moved_one_percent",
                                             "hodograph_degree_factor_missing"};
  for (const std::string& m : mistakes) {
    copy_tree(klass / ("mistake_" + m));
    apply_mistake(klass / ("mistake_" + m), m);
  }
  // Tested only with the defaults: t is the default 0.6, not the parameter.
  copy_tree(klass / "hidden_t_fixed");
  edit(klass / "hidden_t_fixed", kLabFile, "const sp::DeCasteljau d = sp::de_casteljau(c, s.get(\"t\"));",
       "const sp::DeCasteljau d = sp::de_casteljau(c, 0.6);");
  copy_tree(klass / "no_compile");
  edit(klass / "no_compile", kLabFile, "void init() {", "void init() { this is not C++;");

  const fs::path other = klass / "correct_01" / "notes.txt";
  copy_tree(klass / "hostile_reads");
  hostile_init(klass / "hostile_reads", "#include <cstdio>\n#include <cstdlib>\n",
               "  for (const char* p : {\"" + other.string() + "\", \"" +
                   (kSourceDir / "reference_images" / (kLab + "__de_casteljau.png")).string() + "\"}) {\n"
                   "    std::FILE* f = std::fopen(p, \"rb\");\n"
                   "    if (!f) { std::fprintf(stderr, \"cannot read %s\\n\", p); std::exit(1); }\n"
                   "    for (int c; (c = std::fgetc(f)) != EOF;) std::fputc(c, stderr);\n"
                   "  }");
  copy_tree(klass / "hostile_configure");
  edit(klass / "hostile_configure", "CMakeLists.txt", "project(gllab",
       "file(WRITE \"" + canary.string() + "\" \"overwritten\\n\")\n"
       "file(WRITE \"${CMAKE_CURRENT_SOURCE_DIR}/labs/" + kLab + "/written.txt\" \"x\")\nproject(gllab");
  copy_tree(klass / "hostile_socket");
  hostile_init(klass / "hostile_socket", "#include <arpa/inet.h>\n#include <cstdio>\n#include <cstdlib>\n"
               "#include <sys/socket.h>\n#include <unistd.h>\n",
               "  const int fd = socket(AF_INET, SOCK_STREAM, 0);\n"
               "  sockaddr_in a{};\n  a.sin_family = AF_INET;\n  a.sin_port = htons(" +
                   std::to_string(listener.port()) + ");\n"
                   "  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);\n"
                   "  if (connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {\n"
                   "    std::perror(\"connect to the grader\");\n    std::exit(1);\n  }\n  close(fd);");
  copy_tree(klass / "hostile_fork_bomb");
  // It says when a fork fails, then waits, as every copy does.
  hostile_init(klass / "hostile_fork_bomb", "#include <cstdio>\n#include <unistd.h>\n",
               "  for (;;)\n    if (fork() < 0) {\n      std::perror(\"fork\");\n      pause();\n    }");
  copy_tree(klass / "hostile_fills_disk");
  hostile_init(klass / "hostile_fills_disk", "#include <cstdio>\n#include <vector>\n",
               "  std::FILE* f = std::fopen(\"fill.bin\", \"wb\");\n  std::vector<char> block(1 << 20, 'x');\n"
               "  for (;;) std::fwrite(block.data(), 1, block.size(), f);");
  copy_tree(klass / "hostile_sleeps");
  hostile_init(klass / "hostile_sleeps", "#include <unistd.h>\n", "  for (;;) sleep(1000);");

  // The copier: the references, committed as answers/ and built into the
  // program (.incbin, as common/gl/glut_shapes_replay.cpp embeds its
  // recording), pasted over each view after it drew its text.
  const fs::path copier = klass / "copier";
  copy_tree(copier);
  fs::create_directories(copier / "labs" / kLab / "answers");
  const std::vector<std::pair<std::string, std::string>> views = {
      {"de_casteljau", "draw_scheme"},    {"bernstein", "draw_bernstein"},
      {"convex_hull", "draw_hulls"},      {"subdivision", "draw_subdivision"},
      {"degree_elevation", "draw_degree_elevation"}, {"hodograph", "draw_hodograph"}};
  for (const auto& [view, draw] : views)
    fs::copy_file(kSourceDir / "reference_images" / (kLab + "__" + view + ".png"),
                  copier / "labs" / kLab / "answers" / (view + ".png"));
  // The build sees its tree at /submission/src (tools/class_build.h).
  std::string embed = "#include <cstdint>\n#include \"image/image.h\"\n";
  for (std::size_t k = 0; k < views.size(); ++k) {
    const std::string n = "answer" + std::to_string(k);
    embed += "asm(\".section .rodata\\n.globl " + n + "\\n" + n + ":\\n.incbin \\\"" + "/submission/src/labs/" + kLab +
             "/answers/" + views[k].first + ".png\\\"\\n.globl " + n + "_end\\n" + n + "_end:\\n.previous\\n\");\n"
             "extern \"C\" const std::uint8_t " + n + "[], " + n + "_end[];\n";
  }
  embed +=
      "void paste(const std::uint8_t* b, const std::uint8_t* e) {\n"
      "  const gllab::Image im = gllab::decode_png(b, std::size_t(e - b), \"answer\");\n"
      "  glPushAttrib(GL_ALL_ATTRIB_BITS);\n  glDisable(GL_DEPTH_TEST);\n  glDisable(GL_LIGHTING);\n"
      "  glDisable(GL_TEXTURE_2D);\n  glDisable(GL_BLEND);\n  glPixelZoom(1, -1);\n"
      "  glWindowPos2i(0, im.height);\n"
      "  glDrawPixels(im.width, im.height, GL_RGBA, GL_UNSIGNED_BYTE, im.rgba.data());\n  glPopAttrib();\n}\n";
  edit(copier, kLabFile, "namespace {\n\nnamespace sp", embed + "namespace {\n\nnamespace sp");
  for (std::size_t k = 0; k < views.size(); ++k) {
    const std::string f = views[k].second, n = "answer" + std::to_string(k);
    edit(copier, kLabFile, ", " + f + "}", ", [](const gllab::State& s) { " + f + "(s); paste(" + n + ", " + n + "_end); }}");
  }

  const auto before_class = snapshot(klass), before_refs = snapshot(kSourceDir / "reference_images");
  const std::string canary_before = file_text(canary);
  const fs::path csv = dir / "class.csv", report = dir / "report";
  const auto start = std::chrono::steady_clock::now();
  const gllab::ProcessResult r =
      run_process({(kBinDir / "labgrade").string(), "--class", klass.string(), "--labs", "12", "--hidden", "2",
                   "--seed", "20261206", "--work", work.string(), "--csv", csv.string(), "--report", report.string(),
                   "--timeout", "3", "--quiet"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_status, 1) << r.out << r.err;  // some students fail
  std::printf("labgrade --class (cold base cache, 23 students): %.1f s\n%s\n", seconds, r.out.c_str());
  auto rows = read_csv(file_text(csv));
  ASSERT_EQ(rows.size(), 23u) << file_text(csv);

  for (const std::string& s : correct) {
    SCOPED_TRACE(s);
    EXPECT_EQ(rows[s]["kind"], "source");
    EXPECT_EQ(rows[s]["build"], "built");
    EXPECT_EQ(rows[s]["passed"], "6");
    EXPECT_EQ(rows[s]["hidden"], "12");
    EXPECT_EQ(rows[s]["hidden_passed"], "12");
    EXPECT_EQ(rows[s]["score"], "100.0");
    EXPECT_GT(std::stod(rows[s]["cache_hit_rate"]), 90.0) << "unchanged files come from the base cache";
  }
  for (const std::string& m : mistakes) {
    SCOPED_TRACE(m);
    EXPECT_EQ(rows["mistake_" + m]["build"], "built");
    EXPECT_LT(std::stoi(rows["mistake_" + m]["passed"]), 6);
  }
  EXPECT_EQ(rows["hidden_t_fixed"]["passed"], "6") << "the default pictures hide it";
  EXPECT_LT(std::stoi(rows["hidden_t_fixed"]["hidden_passed"]), 12) << "hidden inputs show it";
  EXPECT_EQ(rows["no_compile"]["build"], "failed");
  EXPECT_NE(rows["no_compile"]["reason"].find("build failed"), std::string::npos) << rows["no_compile"]["reason"];
  EXPECT_NE(rows["no_compile"]["reason"].find("error"), std::string::npos) << rows["no_compile"]["reason"];

  EXPECT_EQ(rows["copier"]["passed"], "6") << "the pasted references pass the default views";
  EXPECT_EQ(rows["copier"]["hidden_passed"], "0") << "no hidden render is a shipped reference";

  EXPECT_EQ(rows["hostile_configure"]["build"], "failed");
  EXPECT_NE(rows["hostile_configure"]["reason"].find("configure failed"), std::string::npos)
      << rows["hostile_configure"]["reason"];
  for (const char* h : {"hostile_reads", "hostile_socket", "hostile_fork_bomb", "hostile_fills_disk",
                        "hostile_sleeps"}) {
    SCOPED_TRACE(h);
    EXPECT_EQ(rows[h]["build"], "built");
    EXPECT_EQ(rows[h]["passed"], "0");
    EXPECT_EQ(rows[h]["hidden_passed"], "0");
  }
  const auto reason = [&](const std::string& s) { return file_text(report / s / "results.json"); };
  EXPECT_NE(reason("hostile_reads").find("cannot read"), std::string::npos) << reason("hostile_reads");
  EXPECT_NE(reason("hostile_socket").find("connect to the grader"), std::string::npos) << reason("hostile_socket");
  EXPECT_NE(reason("hostile_fork_bomb").find("process limit"), std::string::npos) << reason("hostile_fork_bomb");
  EXPECT_NE(reason("hostile_fills_disk").find("file size limit"), std::string::npos) << reason("hostile_fills_disk");
  EXPECT_NE(reason("hostile_sleeps").find("wall-clock limit"), std::string::npos) << reason("hostile_sleeps");

  // Nothing outside the sandbox changed: the trees, the references, the
  // instructor's file; no connection reached the grader; no secret leaked.
  EXPECT_EQ(snapshot(klass), before_class);
  EXPECT_EQ(snapshot(kSourceDir / "reference_images"), before_refs);
  EXPECT_EQ(file_text(canary), canary_before);
  EXPECT_EQ(listener.accepted(), 0);
  for (const auto& e : fs::recursive_directory_iterator(dir.path())) {
    if (e.is_regular_file() && e.path().string().find("/class/") == std::string::npos) {
      EXPECT_EQ(file_text(e.path()).find(kSecret), std::string::npos) << e.path();
    }
  }
  EXPECT_EQ(r.out.find(kSecret), std::string::npos);

  // The report: an index row per student, each page loads in headless Chromium.
  const std::string index = file_text(report / "index.html");
  for (const auto& [student, row] : rows) EXPECT_NE(index.find(student + "/index.html"), std::string::npos) << student;
  EXPECT_NE(file_text(report / "hidden_t_fixed" / "index.html").find("--set t="), std::string::npos)
      << "a failing hidden render shows its inputs";
  ASSERT_TRUE(fs::exists("/usr/bin/chromium")) << "chromium is missing: ./lab installs it";
  const auto dom = [&](const fs::path& page) {
    const gllab::ProcessResult c = gllab::testing::chromium_dom(page);
    EXPECT_EQ(c.exit_status, 0) << c.err;
    return c.out;
  };
  EXPECT_NE(dom(report / "index.html").find("<title>gllab class: 23 students</title>"), std::string::npos);
  // hidden_t_fixed's page: 6 views x 3 images, and its failing hidden renders x 3, all loaded.
  const std::string page = dom(report / "hidden_t_fixed" / "index.html");
  const auto title = page.find("<title>gllab grade: images ");
  ASSERT_NE(title, std::string::npos) << page.substr(0, 400);
  const std::string counts = page.substr(title + 27, page.find(" loaded", title) - title - 27);
  EXPECT_EQ(counts.substr(0, counts.find('/')), counts.substr(counts.find('/') + 1)) << counts;
  EXPECT_GT(std::stoi(counts.substr(counts.find('/') + 1)), 18) << counts;

  // Part of the class again (the hostile ones each cost their timeouts, and
  // are graded above), one process per student, 2 at a time, with the warm
  // cache: the merged CSV has the same rows.
  const fs::path part = dir / "part";
  fs::create_directories(part);
  for (const char* s : {"correct_01", "correct_02", "correct_03", "hidden_t_fixed", "no_compile", "copier",
                        "mistake_de_casteljau_one_minus_t"})
    fs::create_directory_symlink(klass / s, part / s);
  for (auto it = rows.begin(); it != rows.end();) it = fs::exists(part / it->first) ? std::next(it) : rows.erase(it);
  const auto warm = std::chrono::steady_clock::now();
  const gllab::ProcessResult p = run_process(
      {(kSourceDir / "examples" / "grade_class_parallel.sh").string(), part.string(), (dir / "parallel").string(), "2",
       "--labs", "12", "--hidden", "2", "--seed", "20261206", "--work", work.string(), "--timeout", "3"},
      {"LABGRADE=" + (kBinDir / "labgrade").string()});
  const double warm_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - warm).count();
  EXPECT_EQ(p.exit_status, 1) << p.out << p.err;
  std::printf("grade_class_parallel.sh -j 2 (warm cache, 7 students): %.1f s\n", warm_seconds);
  auto merged = read_csv(file_text(dir / "parallel" / "class.csv"));
  ASSERT_EQ(merged.size(), rows.size());
  for (auto& [student, row] : rows) {
    SCOPED_TRACE(student);
    for (const char* column : {"kind", "views", "passed", "hidden", "hidden_passed", "score", "build"})
      EXPECT_EQ(merged[student][column], row[column]) << column;
  }
  for (const char* s : {"correct_01", "correct_02", "correct_03"})
    EXPECT_EQ(merged[s]["cache_hit_rate"], "100.0") << s << ": its own cache answers every file";
  EXPECT_EQ(snapshot(klass), before_class);
}

}  // namespace
