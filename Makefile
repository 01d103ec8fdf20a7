# Two commands on a fresh Debian 12 machine: `make run` and `make test`.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)

.PHONY: all deps configure build run test bench docs clean web web-serve

all: build

deps:
	@bash scripts/install-deps.sh

# A unity build (several sources to a translation unit) compiles each header
# fewer times: a fresh build is quicker, and renders the same images as
# fast. UNITY_BUILD=OFF compiles each source alone.
UNITY_BUILD ?= ON
configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=$(UNITY_BUILD) \
	  -DSCENEFILE_TOOL_LAUNCHER= >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Renders the default scene, then runs each tool on the bundled examples.
run: build
	@bash scripts/run-example.sh $(BUILD_DIR)

test: build web
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The page (web/, docs/WEB.md): the library and the renderer compiled to
# WebAssembly by Debian's emscripten, and the page bundled, into the static
# folder $(BUILD_DIR)/web; web-serve serves it on localhost with the headers
# that threads need.
WEB_PORT ?= 8043
web: deps
	@bash scripts/build-web.sh $(BUILD_DIR) $(JOBS)
web-serve: web
	@python3 scripts/web-serve.py $(BUILD_DIR)/web --port $(WEB_PORT)

# The API reference, from the public headers (Doxygen): $(BUILD_DIR)/docs/html;
# the pictures of docs/GUIDE.md, from the scenes in the repository;
# docs/EDITORS.md's, of Neovim with sfls; and docs/WEB.md's, of the page.
docs: configure web
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target docs docs-images docs-editor-images docs-web-images
	@echo "The API reference is in $(BUILD_DIR)/docs/html/index.html; the guide's pictures in docs/images/guide, the editors' in docs/images/editors, the page's in docs/images/web."

bench: build
	@bash bench/run.sh $(BUILD_DIR)
	@bash bench/render_bench.sh $(BUILD_DIR)
	@bash bench/render_suite.sh $(BUILD_DIR)
	@bash bench/tracers.sh $(BUILD_DIR)
	@bash bench/equal_error.sh $(BUILD_DIR)
	@bash bench/tiles_bench.sh $(BUILD_DIR)
	@bash bench/sfls_bench.sh $(BUILD_DIR)
	@bash bench/web_bench.sh $(BUILD_DIR)

# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (but the label "slurm", which tests the Slurm scripts on a cluster, not memory safety):
# the first finding, a leak included, aborts the program and fails its test.
# tests/sanitizers/lsan.supp says which leaks are not ours, and why.
SANITIZE_DIR ?= build-sanitize
SANITIZE_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizers/lsan.supp:print_suppressions=0
.PHONY: test-sanitize
# -O1 -g1 (line tables): what AddressSanitizer's own documentation advises,
# and half the compile time of -O2 -g, which was most of this stage. -g1
# writes no variable's location, but gcc tracks them all the same unless
# told not to (-fno-var-tracking: the same code, and a test program's
# sources in 31 s rather than 51). A unity build (several sources to a
# translation unit) compiles each header fewer times: this stage builds from
# scratch.
test-sanitize: deps
	@cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -fno-var-tracking -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
	  -DSCENEFILE_SANITIZE=address,undefined >/dev/null
	@cmake --build $(SANITIZE_DIR) -j $(JOBS)
	@cd $(SANITIZE_DIR) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -LE slurm

# The tools' end-to-end tests (ctest label "valgrind") with every run of sfcheck,
# sfconvert and sfrender under valgrind: any invalid access, use of an
# uninitialised value, or definite or indirect leak fails the test. They run
# the Release build's tools ($(BUILD_DIR)), compiled once for make test and
# this: its tree takes valgrind as the tools' launcher for the run, and drops
# it after (configure names no launcher, should a run be cut short). Its
# binaries have no line tables, so a report names each frame's function, not
# its line. --read-inline-info=no matters only for a tree built with them
# (RelWithDebInfo -g1: a tool started in 1.6 s under valgrind rather than
# 2.1 without the inlined frames, and start-up is most of each test).
VALGRIND = valgrind;-q;--read-inline-info=no;--error-exitcode=99;--leak-check=full;--errors-for-leak-kinds=definite,indirect;--show-leak-kinds=definite,indirect;--suppressions=$(CURDIR)/tests/sanitizers/valgrind.supp
.PHONY: test-valgrind
test-valgrind: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target sfcheck sfconvert sfrender sfrender_oiio
	@cmake -S . -B $(BUILD_DIR) "-DSCENEFILE_TOOL_LAUNCHER=$(VALGRIND)" >/dev/null
	@status=0; (cd $(BUILD_DIR) && ctest -L valgrind -LE slurm --output-on-failure -j $(JOBS)) || \
	  status=$$?; cmake -S . -B $(BUILD_DIR) -DSCENEFILE_TOOL_LAUNCHER= >/dev/null; exit $$status

# libFuzzer on every reader and on sfconvert's whole path, under ASan and
# UBSan (tests/fuzz, scripts/fuzz.sh): FUZZ_SECONDS per target (FUZZ_JOBS
# jobs each); fuzz-ci is the bounded run of CI, 30 s a target on top of the
# corpus (the long runs are make fuzz's). Findings fail the target.
FUZZ_SECONDS ?= 600
.PHONY: fuzz fuzz-ci
fuzz: deps
	@bash scripts/fuzz.sh $(FUZZ_SECONDS)
fuzz-ci: deps
	@bash scripts/fuzz.sh 30

clean:
	rm -rf $(BUILD_DIR)
