# gllab — the conventional interface. ./lab installs the Debian packages that
# are missing and then calls these targets; with the packages present, use
# make directly.
#
#   make             configure (Release) and build into build/; HEADLESS=egl|osmesa|auto
#                    picks the headless backend (default auto: EGL when libEGL is
#                    found, else OSMesa; docs/platform.md), e.g. make test HEADLESS=osmesa
#   make target TARGETS="15_bspline_curves"   build only these programs and
#                    what they link (./lab open and ./lab render use it)
#   make run         grade this build: render every lab view headless, compare
#                    with reference_images/, print a table; the report (renders,
#                    heat maps, results.json/.csv) goes to out/index.html
#   make grade GRADE_ARGS="--images DIR"   labgrade with these arguments
#   make test        build and run the whole test suite through CTest
#   make references  re-render reference_images/ and reference_images/MANIFEST
#   make calibration re-measure the grading metric, rewrite README's numbers
#   make backends    link every lab over OSMesa too (build/osmesa/) and check that
#                    every view is byte-identical to the EGL build's (CI runs it)
#   make sanitize    build in build-sanitize/ with GCC, ASan + UBSan and run the tests
#   make clang       the same with clang -O1 in build-clang/ (CI's sanitizer build and
#                    its second compiler); its renders are graded against the
#                    GCC-built references there
#   make bench       build bench/ in build-bench/ (Release, GLLAB_BENCH=ON) and run
#                    spline_bench against GLU, SISL and OpenCASCADE, then
#                    submission_bench (lab 05's four paths, Mtri/s and ratios),
#                    iso_bench (marching cubes against VTK), ffd_bench (free-form
#                    deformation of 10^6 vertices: textbook and fast layer),
#                    space_bench (ray queries: scene octree, brute force, Embree),
#                    csg_bench (lab 33's stencil CSG against OpenCSG, frames/s;
#                    ray-CSG rays/s; in a window, under xvfb-run without a display),
#                    then grade_bench (labgrade over every view: wall seconds);
#                    flags for spline_bench go in BENCH_ARGS, e.g.
#                    make bench BENCH_ARGS=--benchmark_filter=curve
#   make fuzz        build the libFuzzer targets of tests/fuzz/ in build-fuzz/ with clang
#                    (ASan + UBSan) and run each for FUZZ_SECONDS (default 60) seconds;
#                    FUZZ_OPT=-O0 builds twice as fast, runs slower (CI uses it)
#                    (tests/fuzz/README.md; needs clang and libclang-rt-dev)
#   make clean       remove build/, build-sanitize/, build-clang/, build-bench/, build-fuzz/ and out/

BUILD ?= build
SANITIZE_BUILD ?= build-sanitize
CLANG_BUILD ?= build-clang
BENCH_BUILD ?= build-bench
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_OPT ?= -O1
# The headless backend (CMakeLists.txt, GLLAB_HEADLESS); empty keeps what build/ has.
HEADLESS ?=
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all configure build target run grade test references calibration backends sanitize clang bench fuzz clean

all: build

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(if $(HEADLESS),-DGLLAB_HEADLESS=$(HEADLESS))

# HEADLESS given: configure again with it (only the runner and what links it change).
configure: $(BUILD)/CMakeCache.txt
	$(if $(HEADLESS),cmake -S . -B $(BUILD) -DGLLAB_HEADLESS=$(HEADLESS) > /dev/null,@:)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

target: configure
	cmake --build $(BUILD) -j $(JOBS) --target $(TARGETS)

run: build
	$(BUILD)/bin/labgrade --build $(BUILD) --report out

grade: build
	$(BUILD)/bin/labgrade $(GRADE_ARGS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

references: build
	$(BUILD)/bin/labrun --update-references
	@echo "look at every image before committing; then: make calibration"

# Every view rendered by the EGL build and by the same lab code linked over
# OSMesa (build/osmesa/), compared byte for byte; then the twins are switched
# off again, so build/ keeps one program per lab.
backends: build
	cmake -S . -B $(BUILD) -DGLLAB_OSMESA_TWINS=ON > /dev/null
	status=0; cmake --build $(BUILD) -j $(JOBS) --target osmesa_twins && \
	  $(BUILD)/bin/labrun --compare-builds $(BUILD)/osmesa || status=$$?; \
	  cmake -S . -B $(BUILD) -DGLLAB_OSMESA_TWINS=OFF > /dev/null; exit $$status

# Re-measure the grading metric (softpipe over every view, every real
# mistake) and rewrite README.md's calibration block.
calibration: build
	GLLAB_UPDATE_CALIBRATION=1 ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -R grading/Calibration

# The sanitizers' settings for the tests. LeakSanitizer: only Mesa's known
# context leak is suppressed (.ci/lsan.supp). intercept_tls_get_addr=0:
# LeakSanitizer's own tracker of dynamic TLS reads a stale entry in lab 21's
# display_list view with --print-text and crashes (docs/platform.md, "Sanitizers").
SANITIZER_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:intercept_tls_get_addr=0 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/.ci/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# GCC with ASan + UBSan: every test (the grading calibration aside: CMakeLists.txt,
# GLLAB_GRADING_FIXTURES).
sanitize:
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLLAB_SANITIZE=ON -DGLLAB_GRADING_FIXTURES=OFF
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	$(SANITIZER_ENV) ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j $(JOBS)

# The second compiler and CI's sanitizer build in one: clang with ASan + UBSan
# at -O1 with line tables only (the file and line the sanitizers' reports need,
# not full debug information), the same tests as make sanitize, and every view
# graded in the build profile against the references GCC -O2 made (a benign build).
CLANG_FLAGS = -O1 -gline-tables-only -DNDEBUG
clang:
	cmake -S . -B $(CLANG_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
	  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(CLANG_FLAGS)" \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(CLANG_FLAGS)" -DGLLAB_SANITIZE=ON -DGLLAB_GRADING_FIXTURES=OFF
	cmake --build $(CLANG_BUILD) -j $(JOBS)
	$(SANITIZER_ENV) ctest --test-dir $(CLANG_BUILD) --output-on-failure -j $(JOBS)

# A separate build directory: the normal build never needs the peers (bench/README.md).
bench:
	cmake -S . -B $(BENCH_BUILD) -DCMAKE_BUILD_TYPE=Release -DGLLAB_BENCH=ON
	cmake --build $(BENCH_BUILD) -j $(JOBS) --target spline_bench submission_bench iso_bench ffd_bench space_bench grade_bench
	$(BENCH_BUILD)/bin/spline_bench $(BENCH_ARGS)
	$(BENCH_BUILD)/bin/submission_bench $(SUBMISSION_BENCH_ARGS)
	$(BENCH_BUILD)/bin/iso_bench $(ISO_BENCH_ARGS)
	$(BENCH_BUILD)/bin/ffd_bench $(FFD_BENCH_ARGS)
	$(BENCH_BUILD)/bin/space_bench $(SPACE_BENCH_ARGS)
	@if cmake --build $(BENCH_BUILD) --target help | grep -q ' csg_bench'; then \
	  cmake --build $(BENCH_BUILD) -j $(JOBS) --target csg_bench && \
	  if [ -n "$$DISPLAY" ]; then $(BENCH_BUILD)/bin/csg_bench $(CSG_BENCH_ARGS); \
	  else xvfb-run -a -s "-screen 0 1024x768x24" $(BENCH_BUILD)/bin/csg_bench $(CSG_BENCH_ARGS); fi; \
	else echo "csg_bench: OpenCSG is not installed (libopencsg-dev; ./lab bench installs it): skipped"; fi
	$(BENCH_BUILD)/bin/grade_bench $(GRADE_BENCH_ARGS)

# The fuzzers (tests/fuzz/README.md): every library they link compiled for coverage
# with ASan + UBSan at FUZZ_OPT; the labs and the test suite are not built there.
fuzz:
	tests/fuzz/run.sh check
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DGLLAB_FUZZ=ON \
	  -DCMAKE_BUILD_TYPE=Fuzz -DCMAKE_CXX_FLAGS_FUZZ="$(FUZZ_OPT) -gline-tables-only" \
	  -DCMAKE_C_FLAGS_FUZZ="$(FUZZ_OPT) -gline-tables-only"
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_json fuzz_options fuzz_grading
	tests/fuzz/run.sh run $(FUZZ_BUILD) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(CLANG_BUILD) $(BENCH_BUILD) $(FUZZ_BUILD) out
