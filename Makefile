# fragsim: one Makefile.  `make` builds libfragsim.a and the fragsim CLI.
# Sources are found by directory, so a new stage or unit is a new file.

CC ?= cc
CXX ?= c++
BUILD ?= build
OPT ?= -O2
PKGS_CORE := osmesa snappy zlib inih jansson libgpiod
# -ffp-contract=off: every float operation rounds separately, as llvmpipe's
# do, also in the functions built for FMA (clang would otherwise fuse a*b+c
# there, and gcc outside strict ISO modes).
CFLAGS_BASE := -std=c11 -D_POSIX_C_SOURCE=200809L -g $(OPT) -Wall -Wextra -Werror \
	-fno-strict-aliasing -Wno-missing-field-initializers -ffp-contract=off
CFLAGS += $(CFLAGS_BASE) $(SAN)
CXXFLAGS += -std=c++17 -g $(OPT) -Wall -Wextra -Werror -ffp-contract=off $(SAN)
LDFLAGS += $(SAN)
PKG_LIBS = $(shell pkg-config --libs $(PKGS_CORE) 2>/dev/null || echo -lOSMesa -lsnappy -lz -linih -ljansson -lgpiod)
OIIO_LIBS = $(shell pkg-config --libs OpenImageIO 2>/dev/null || echo -lOpenImageIO -lOpenImageIO_Util)

# The library core: C only, no OSMesa and no OpenImageIO.
LIB_SRCS := $(wildcard pipeline/*.c units/*.c rtl_model/*.c) \
	$(filter-out driver/cli_%.c driver/osmesa_%.c driver/shim_%.c, $(wildcard driver/*.c))
# CLI and tools: the OSMesa reference runner and the OpenImageIO wrapper.
CLI_SRCS := $(wildcard driver/cli_*.c driver/osmesa_*.c)
CLI_CXX := $(wildcard driver/*.cpp)
TEST_SRCS := $(wildcard tests/test_*.c)
SCENE_SRCS := $(wildcard traces/*.c)

LIB_OBJS := $(LIB_SRCS:%.c=$(BUILD)/%.o)
CLI_OBJS := $(CLI_SRCS:%.c=$(BUILD)/%.o) $(CLI_CXX:%.cpp=$(BUILD)/%.o)
TEST_BINS := $(TEST_SRCS:tests/%.c=$(BUILD)/tests/%)
SCENEGEN := $(BUILD)/scenegen
# The shim driver: GL and OSMesa entry points in a shared library, so that an
# OSMesa program runs on the model (driver/shim_*.c).  Debian's gcc builds PIE
# by default, which cannot go into a shared object, so the library core is
# compiled again with -fPIC into $(BUILD)/pic/; hidden visibility exports only
# the GL and OSMesa names.  It needs neither OSMesa nor OpenImageIO.
SHIM_SRCS := $(wildcard driver/shim_*.c)
PIC_OBJS := $(LIB_SRCS:%.c=$(BUILD)/pic/%.o) $(SHIM_SRCS:%.c=$(BUILD)/pic/%.o)
SHIM := $(BUILD)/libfragsimGL.so
SHIM_LIBS = $(shell pkg-config --libs snappy zlib inih jansson libgpiod 2>/dev/null || echo -lsnappy -lz -linih -ljansson -lgpiod)
LIB := $(BUILD)/libfragsim.a
FRAGSIM := $(BUILD)/fragsim
# One static library per layer (docs/architecture.md, "Layers";
# tests/cli_layers.sh checks the includes), linked from the top layer down:
# driver/, rtl_model/, then pipeline/ and units/.  libfragsim.a holds all
# of them in one, for the scripts that link it by hand (fuzz.sh, sweep_study.sh).
LAYER_LIBS := $(BUILD)/libfragsim_driver.a $(BUILD)/libfragsim_rtl.a $(BUILD)/libfragsim_core.a
# Link the archives whole so that every executor overrides its weak fallback.
WHOLE_LIB = -Wl,--whole-archive $(LAYER_LIBS) -Wl,--no-whole-archive

.PHONY: all deps test run sanitize tsan fuzz bench golden docs clean scenes tests shim study-filters exec-check gl-coverage
.PHONY: sampling-study studies study-occlusion study-query-cost study-texture-cache study-culling conformance conformance-run
all: $(LIB) $(FRAGSIM) tests scenes shim exec-check cullstudy

deps:
	@scripts/deps.sh

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(shell pkg-config --cflags OpenImageIO 2>/dev/null) -MMD -MP -c $< -o $@

$(BUILD)/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC -fvisibility=hidden -MMD -MP -c $< -o $@

$(BUILD)/libfragsim_core.a: $(filter $(BUILD)/pipeline/% $(BUILD)/units/%,$(LIB_OBJS))
$(BUILD)/libfragsim_rtl.a: $(filter $(BUILD)/rtl_model/%,$(LIB_OBJS))
$(BUILD)/libfragsim_driver.a: $(filter $(BUILD)/driver/%,$(LIB_OBJS))
$(LAYER_LIBS):
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(LIB): $(LIB_OBJS) $(LAYER_LIBS)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $(LIB_OBJS)

$(FRAGSIM): $(CLI_OBJS) $(LIB)
	$(CXX) $(LDFLAGS) -o $@ $(CLI_OBJS) $(WHOLE_LIB) $(PKG_LIBS) $(OIIO_LIBS) -lm

shim: $(SHIM)
$(SHIM): $(PIC_OBJS)
	$(CC) $(LDFLAGS) -shared -Wl,-soname,libfragsimGL.so -Wl,-z,defs -o $@ $(PIC_OBJS) $(SHIM_LIBS) -lm

# The executors in pipeline/ and units/ define the prototypes the command
# table generates (driver/gl_call.h) without including them (the layers):
# each of those files is compiled once more with them, so that a definition
# unlike its table row fails the build instead of the call (no object made).
EXEC_CHECKS := $(patsubst %.c,$(BUILD)/exec_check/%.ok,$(wildcard pipeline/*.c units/*.c))
exec-check: $(EXEC_CHECKS)
$(BUILD)/exec_check/%.ok: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -include driver/gl_call.h -fsyntax-only -MMD -MP -MF $@.d -MT $@ $< && touch $@

tests: $(TEST_BINS)
$(BUILD)/tests/%: $(BUILD)/tests/%.o $(LIB) $(filter-out $(BUILD)/driver/cli_main.o,$(CLI_OBJS))
	$(CXX) $(LDFLAGS) -o $@ $< $(filter-out $(BUILD)/driver/cli_main.o,$(CLI_OBJS)) $(WHOLE_LIB) $(PKG_LIBS) $(OIIO_LIBS) -lm

# One generator program for every scene: traces/*.c.
scenes: $(SCENEGEN)
$(SCENEGEN): $(SCENE_SRCS:%.c=$(BUILD)/%.o) $(LIB)
	$(CC) $(LDFLAGS) -o $@ $(SCENE_SRCS:%.c=$(BUILD)/%.o) $(WHOLE_LIB) $(PKG_LIBS) -lm

# The culling study (traces/culling/, issue 21): one OSMesa program built
# against the shim (cullstudy: the model) and against libOSMesa
# (cullstudy-osmesa: llvmpipe).  The scene generators' emitter and the city
# are compiled again with SG_DIRECT_GL, so they send plain gl* calls.
CULL_SRCS := $(wildcard traces/culling/*.c)
CULL_GEOM := traces/sg.c traces/scene_city.c traces/scene_cathedral.c traces/scene_forest.c traces/scene_garbage.c
CULL_OBJS := $(CULL_SRCS:%.c=$(BUILD)/cull/%.o) $(CULL_GEOM:%.c=$(BUILD)/cull/%.o)
CULLSTUDY := $(BUILD)/cullstudy $(BUILD)/cullstudy-osmesa
.PHONY: cullstudy
cullstudy: $(CULLSTUDY)
$(BUILD)/cull/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -DSG_DIRECT_GL -MMD -MP -c $< -o $@
$(BUILD)/cullstudy: $(CULL_OBJS) $(SHIM)
	$(CC) $(LDFLAGS) -o $@ $(CULL_OBJS) -L$(BUILD) -lfragsimGL -Wl,-rpath,$(abspath $(BUILD)) -lz -lm
$(BUILD)/cullstudy-osmesa: $(CULL_OBJS)
	$(CC) $(LDFLAGS) -o $@ $(CULL_OBJS) -lOSMesa -lz -lm

test: deps all
	@tests/run_all.sh $(BUILD)

run: deps all
	@scripts/run_demo.sh $(BUILD)

sanitize:
	$(MAKE) BUILD=build-san OPT=-O1 SAN="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" all
	FRAGSIM_SKIP_COMPILER_TEST=1 ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 tests/run_all.sh build-san

# ThreadSanitizer on the threaded rasterization (pipeline/raster_threads.h):
# the threaded replay test (tests/cli_threads.sh) on a TSan build; any data
# race report fails it (halt_on_error).
tsan:
	$(MAKE) BUILD=build-tsan OPT=-O1 SAN="-fsanitize=thread -fno-omit-frame-pointer" build-tsan/fragsim build-tsan/scenegen
	FRAGSIM=$(abspath build-tsan/fragsim) SCENEGEN=$(abspath build-tsan/scenegen) TSAN_OPTIONS="halt_on_error=1 exitcode=66" THREADS_QUICK=1 bash tests/cli_threads.sh

# Fuzzing the trace path and the GL API (scripts/fuzz.sh, tests/fuzz/README.md;
# FUZZ_SECONDS per harness, default 150).
fuzz: deps all
	$(MAKE) BUILD=build-fuzz CC=clang OPT=-O1 SAN="-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" build-fuzz/libfragsim.a
	@scripts/fuzz.sh $(BUILD) build-fuzz

bench: deps all
	@scripts/bench.sh $(BUILD)

# The texture filter quality/cost study: regenerates docs/texture_filtering.md
# (large outputs in out/study-filters).
study-filters: $(FRAGSIM)
	@scripts/study_filters.sh $(BUILD)

golden: all
	@scripts/golden.sh $(BUILD)

# The culling study (issue 21; Huettner 1999, sec. 3.1.9): regenerates
# docs/studies/culling.md and its plots (large outputs in out/study-culling;
# FRAMES=N sets the path's frames, default 10).
study-culling: deps all
	@scripts/study_culling.sh $(BUILD)

# Sampled mode against full cycle mode on the conformance corpus's programs
# and the scenes, O2 and InfiniteReality (issue 24): regenerates
# docs/sampling.md and docs/sampling_error.png (traces in $(BUILD)/sampling).
sampling-study: deps all
	@BUILD=$(BUILD) /usr/bin/python3 scripts/sampling_study.py

# Studies: sweeps of configs/sweeps/NAME.ini into docs/studies/NAME.md and
# its plots (big outputs in out/studies/).
studies: study-occlusion study-query-cost study-texture-cache
study-occlusion: deps all
	@scripts/sweep_study.sh occlusion $(BUILD)
study-query-cost: deps all
	@scripts/sweep_study.sh query_cost $(BUILD)
study-texture-cache: deps all
	@scripts/sweep_study.sh texture_cache $(BUILD)

# The conformance corpus (tests/conformance/): piglit and program traces
# replayed on the model and compared with references from glretrace and an
# independent OSMesa replayer (generated into $(BUILD)/conformance, cached,
# checked against the committed MD5s); rewrites docs/conformance.md.  Run by
# `make test` (tests/cli_conformance.sh).
conformance: deps all
	@$(MAKE) -s --no-print-directory conformance-run
conformance-run:
	@xvfb-run -a -s '-screen 0 1280x1024x24' /usr/bin/python3 tests/conformance/run.py --build $(BUILD)

# Reference pages generated from the config and statistics tables.
docs: all
	@scripts/gen_docs.sh $(BUILD)

# docs/gl_coverage.md: every GL 1.0-1.5 entry point of the system headers and
# whether this build exports and executes it (tests/cli_gl_coverage.sh fails
# when it is stale).
gl-coverage: all
	@/usr/bin/python3 scripts/gl_coverage.py --build $(BUILD) --pending tests/gl_coverage_pending.txt

clean:
	rm -rf build build-san build-clang build-fuzz

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
