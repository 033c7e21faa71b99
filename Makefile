# libelastica — the only entry point: deps, build, check, bench, demo, install.
# `make check` on a fresh Debian 12 machine installs what is missing and runs every test.

# the header's EL_VERSION_STRING (include/elastica.h: the one place the version is written)
VERSION      := $(shell sed -n 's/^\#define EL_VERSION_STRING "\(.*\)"$$/\1/p' include/elastica.h)
$(if $(VERSION),,$(error no EL_VERSION_STRING "MAJOR.MINOR.PATCH" line in include/elastica.h))
# soname libelastica.so.0 until 1.0: a public struct may still grow (the README says so; el_abi_digest
# tells a program built against another header); from 1.0 a layout change bumps it
SOVERSION    := 0
BUILD        ?= build
PREFIX       ?= /usr/local
PYTHON       ?= python3
SYSPYTHON    ?= /usr/bin/python3
CC           ?= cc

CFLAGS_BASE  := -std=c99 -Wall -Wextra -Werror -O2 -fPIC -Iinclude -I$(BUILD)/include
DEPS_CFLAGS   = $(shell pkg-config --cflags gsl ipopt 2>/dev/null)
DEPS_LIBS     = $(shell pkg-config --libs gsl ipopt 2>/dev/null) -lm -pthread
CHECK_LIBS    = $(shell pkg-config --libs check 2>/dev/null)

LIB_SRC      := $(wildcard libelastica/*.c)
LIB_OBJ      := $(LIB_SRC:libelastica/%.c=$(BUILD)/obj/%.o)
TEST_SRC     := $(wildcard tests/c/test_*.c)
TEST_BIN     := $(TEST_SRC:tests/c/%.c=$(BUILD)/tests/%)
BENCH_SRC    := $(wildcard bench/*.c)
BENCH_BIN    := $(BENCH_SRC:bench/%.c=$(BUILD)/bench/%)
BENCH_CXX    := $(wildcard bench/*.cc)
BENCH_CXX_BIN := $(BENCH_CXX:bench/%.cc=$(BUILD)/bench/%)
SONAME       := libelastica.so.$(SOVERSION)

# Debian packages (Debian 12 / Ubuntu) the project needs; `make deps` installs the missing ones.
APT_PKGS := build-essential pkg-config libgsl-dev coinor-libipopt-dev check \
            python3-cffi python3-numpy python3-pytest python3-scipy python3-mpmath \
            python3-matplotlib python3-ezdxf python3-pandas python3-venv python3-pip freecad xvfb
# Python packages for the python3 first on PATH (when it is not Debian's).
PIP_PKGS := numpy cffi pytest scipy ezdxf matplotlib pandas
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# $(call apt-install,PACKAGES): install those of PACKAGES that are missing (targets that
# need more than `make deps`: the OCCT comparison of `make bench`, clang for fuzzing)
define apt-install
	@missing=$$(for p in $(1); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make $@: installing $$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
endef

.PHONY: all deps lib check check-stages check-c check-asan check-asan-lib check-fuzz-stage check-install check-python \
        check-python-sys check-python-path check-freecad check-fuzz \
        check-tsan fuzz fuzz-deps fuzz-coverage bench hermite-sets length-recovers occt-dev spiro-dev demo gallery install \
        freecad-install clean

all: deps lib

deps: $(BUILD)/.deps-ok
$(BUILD)/.deps-ok: Makefile
	@missing=$$(for p in $(APT_PKGS); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing $$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@if [ "$$(command -v $(PYTHON))" != "$(SYSPYTHON)" ] && \
	   ! $(PYTHON) -c "import numpy, cffi, pytest, scipy, ezdxf, matplotlib, pandas" 2>/dev/null; then \
	  echo "make deps: pip install $(PIP_PKGS) into $$(command -v $(PYTHON))"; \
	  $(PYTHON) -m pip install -q $(PIP_PKGS); \
	fi
	@mkdir -p $(BUILD) && touch $@

lib: $(BUILD)/libelastica.so $(BUILD)/libelastica.a $(BUILD)/_elastica_abi.py

# The binding's declarations pre-parsed by cffi (out-of-line ABI module, pure Python:
# python/libelastica/_cdef.py), beside the library: the binding loads them instead of
# parsing the header at every start (~40 ms and pycparser's import). Debian's cffi 1.15
# and PyPI's 2.0 write the same bytes, and either Python loads the other's.
# With them the binding's own entry (libelastica/binding.h, not public).
$(BUILD)/_elastica_abi.py: include/elastica.h libelastica/binding.h python/libelastica/_cdef.py | $(BUILD)/.deps-ok
	$(PYTHON) python/libelastica/_cdef.py include/elastica.h $@ libelastica/binding.h

# EL_ABI_DIGEST, the CRC-32 of the header's declarations (the digest above), which
# el_abi_digest returns (libelastica/abi.c): the binding and C programs (elastica_abi.h
# is installed) check at start that the library was built from their header.
$(BUILD)/include/elastica_abi.h: include/elastica.h python/libelastica/_cdef.py | $(BUILD)/.deps-ok
	@mkdir -p $(dir $@)
	$(PYTHON) python/libelastica/_cdef.py --abi include/elastica.h $@
$(BUILD)/obj/abi.o: $(BUILD)/include/elastica_abi.h
# EL_BINDING_DIGEST, binding.h's twin of it (el_binding_digest, libelastica/binding.c): the
# binding calls el_binding_fit only where the library was built from its binding.h.
# binding.h is binding.c's alone (and the fuzz harness's): a change of it rebuilds that
# object, not every one (the wildcard below leaves it out).
$(BUILD)/include/binding_abi.h: libelastica/binding.h python/libelastica/_cdef.py | $(BUILD)/.deps-ok
	@mkdir -p $(dir $@)
	$(PYTHON) python/libelastica/_cdef.py --binding-abi libelastica/binding.h $@
$(BUILD)/obj/binding.o: libelastica/binding.h $(BUILD)/include/binding_abi.h

# The Hermite solver's hot path (its objective, root finding, the elliptic integrals and
# Jacobi functions under it) at -O3 and with sqrt not setting errno (no libm call per
# square root; the library never reads errno, and neither flag changes a result: no
# fast-math): 12 % fewer instructions and ~8 % less time on the tension bench (issue 16);
# the length mode's tracing, the chains and the solutions' end evaluation (smooth.c) too:
# 0.6 % fewer instructions in the length mode, its solution dumps bit for bit the same.
# -fno-trapping-math (no result changes either: it only lets the compiler assume that no
# floating-point exception is trapped, so comparisons and selections of doubles become
# branch-free): the solution sets of 8 x 1000 problems by tension and by length bit for bit
# the same (branch hperf's tools/hermite_sets.c), 1.6-1.8 % less time on 10 000 tension
# problems (paired in one process) for 0.8 % more instructions: the branches it removes
# were mispredicted.
# EXTRA_CFLAGS comes after: the sanitizer builds keep their -O1.
HOT_OBJ := $(addprefix $(BUILD)/obj/,hermite.o hermite_objective.o hermite_poly.o hermite_tension.o hermite_length.o \
             hermite_length_trace.o hermite_length_chart.o hermite_chain.o hermite_near.o hermite_polish.o hermite_lanes.o smooth.o ellint.o jacobi.o)
$(HOT_OBJ): OPT_CFLAGS := -O3 -fno-math-errno -fno-trapping-math
# hermite_lanes.c's four lanes (hermite_lanes_avx2.c) are AVX2 code, run only where the
# processor has it (__builtin_cpu_supports): -mavx2 for that object alone, and no fused
# multiply-add (no -mfma; -ffp-contract=off) so that each lane rounds as the scalar code.
ifneq ($(filter x86_64%,$(shell $(CC) -dumpmachine)),)
$(BUILD)/obj/hermite_lanes_avx2.o: OPT_CFLAGS := -O3 -fno-math-errno -fno-trapping-math -mavx2 -ffp-contract=off
else
$(BUILD)/obj/hermite_lanes_avx2.o: OPT_CFLAGS := -O3 -fno-math-errno -fno-trapping-math
endif
# The fit's hot path (its guess, objective, the discrete model's rows and their Jacobi
# walk, the point-to-curve distances of its report) by the same flags: fewer instructions, the same results (issue 16;
# every output of bench_fit.py's 504 curves compared bit for bit).
FIT_HOT_OBJ := $(addprefix $(BUILD)/obj/,fit_objective.o fit_model.o fit_feet.o fit_nearest.o fit_polygon.o fit_refit.o fit_wander.o fit_lm.o \
               discrete.o guess.o guess_spacing.o fit.o fit_choose.o fit_candidate.o jacobi_walk.o fit_pairing.o)
$(FIT_HOT_OBJ): OPT_CFLAGS := -O3 -fno-math-errno

$(BUILD)/obj/%.o: libelastica/%.c include/elastica.h $(filter-out libelastica/binding.h,$(wildcard libelastica/*.h)) | $(BUILD)/.deps-ok
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_BASE) $(OPT_CFLAGS) $(DEPS_CFLAGS) $(EXTRA_CFLAGS) -c $< -o $@

# libelastica.so -> libelastica.so.0 (the soname) -> libelastica.so.0.1.0 (the file);
# it exports the API only (libelastica/exports.map)
$(BUILD)/libelastica.so: $(LIB_OBJ) libelastica/exports.map
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,--version-script=libelastica/exports.map $(EXTRA_CFLAGS) \
	  -o $(BUILD)/libelastica.so.$(VERSION) $(LIB_OBJ) $(DEPS_LIBS)
	ln -sf libelastica.so.$(VERSION) $(BUILD)/$(SONAME)
	ln -sf $(SONAME) $@

# made afresh: ar r keeps the members of objects whose sources were deleted
$(BUILD)/libelastica.a: $(LIB_OBJ)
	rm -f $@
	ar rcs $@ $^

# ------------------------------------------------------------------ tests

$(BUILD)/tests/%: tests/c/%.c $(wildcard tests/c/*.h) $(BUILD)/libelastica.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_BASE) $(DEPS_CFLAGS) $(EXTRA_CFLAGS) -Itests/c -Ilibelastica $< -o $@ $(BUILD)/libelastica.a $(CHECK_LIBS) $(DEPS_LIBS)

# The fit tests' case any_kernel asserts results that must not depend on OpenBLAS's CPU
# kernel: run again under kernels that gave other results (OPENBLAS_CORETYPE; another BLAS
# ignores it and runs the case as before).
# A kernel needs its instructions: forced on a CPU without them it dies of SIGILL (SkylakeX's
# AVX-512 on an AMD EPYC with AVX2 only), so each runs where /proc/cpuinfo lists its flag
# (kernel:flag; SSE3 is "pni" there) and the run says which it left out.
KERNEL_TESTS     := test_fit_ends_held test_fit_rounding test_fit_keyline_ends
OPENBLAS_KERNELS := Nehalem:sse4_2 Sandybridge:avx Haswell:avx2 SkylakeX:avx512f Zen:avx2 Prescott:pni

# Each test binary's run is a target of its own (<binary>.run), so that make -jN (make check
# runs its stages CHECK_JOBS at a time) runs the C tests side by side instead of one after the
# other: the ASan pass, ~12 CPU-min, was make check's serial critical chain (~13 min wall of
# 15). The heaviest come first (make starts prerequisites in the order listed), so that the
# last ones to end are short; make without -j runs them in that order, one at a time.
# Check's time limits (tcase_set_timeout) are wall clock: CK_TIMEOUT_MULTIPLIER (3 for the
# plain pass unless set; 15 under ASan, below) keeps a box shared with the other stages of
# make check, or with other jobs, from failing a test by "Test timeout expired" (seen at load
# 7-16: test_fit_basin's 60 s, test_fit_ends_held's 120 s) while a hung case still fails.
CK_TIMEOUT_MULTIPLIER ?= 3
HEAVY_TESTS := test_fit_ends_held test_fit_basin test_spline_length test_fit_lbfgs test_fit test_fit_nearest \
               test_hermite_tension test_hermite_length test_spline_reach test_spline_g2 test_hermite_edge \
               test_spline test_fit_paths test_hermite_near
TEST_RUN := $(addsuffix .run,$(foreach t,$(HEAVY_TESTS),$(filter $(BUILD)/tests/$(t),$(TEST_BIN))) \
                             $(filter-out $(HEAVY_TESTS:%=$(BUILD)/tests/%),$(TEST_BIN)))
.PHONY: $(TEST_RUN) check-c-kernels
$(TEST_RUN): %.run: % | lib
	@echo "== $*"; cd tests/c && CK_TIMEOUT_MULTIPLIER=$(CK_TIMEOUT_MULTIPLIER) $(CURDIR)/$*

# KERNEL_RUNS=no (the ASan pass) leaves the kernel loop out: its assertions are those of the
# plain pass, which runs it; ASan ran each of these cases once already (~70 CPU-s saved).
KERNEL_RUNS ?= yes
check-c: $(TEST_RUN) $(if $(filter yes,$(KERNEL_RUNS)),check-c-kernels)
check-c-kernels: lib $(KERNEL_TESTS:%=$(BUILD)/tests/%)
	@set -e; for kf in $(OPENBLAS_KERNELS); do k=$${kf%%:*}; f=$${kf#*:}; \
	  if ! grep -qw "$$f" /proc/cpuinfo; then echo "== OpenBLAS kernel $$k left out: this CPU has no $$f"; continue; fi; \
	  for t in $(KERNEL_TESTS); do echo "== $$t ($$k)"; \
	  (cd tests/c && CK_RUN_CASE=any_kernel CK_TIMEOUT_MULTIPLIER=$(CK_TIMEOUT_MULTIPLIER) OPENBLAS_CORETYPE=$$k \
	     $(CURDIR)/$(BUILD)/tests/$$t); done; done

# The same C tests under AddressSanitizer + UBSan; any report fails the run. The sanitized
# code runs slower (the fit tests most, 1.7 x and more: MUMPS's workspaces, each mapped afresh by
# ASan's allocator), beside another stage of make check: each test case's time limit
# (tcase_set_timeout) is 15 x its plain run's (CK_TIMEOUT_MULTIPLIER; 5 x for the slowdown
# and the plain pass's 3 x for a loaded box). The tests run CHECK_JOBS at a time (the
# jobserver of make check, or make -j check-asan), each once: no OpenBLAS kernel loop.
# clear_shadow_mmap_threshold: ASan zeroes a shadow range above it (64 KB by default) by
# giving its pages back (madvise: they fault in again at the next use), below it by memset.
# MUMPS (under Ipopt: every constrained fit) allocates and frees blocks of 188 KB - 1.5 MB
# at every solve, and the fit tests spent up to half their sanitized CPU in the kernel (sys).
# With memset the shadow's pages stay: the same shadow bytes, the same reports. (No option keeps ASan from mapping the blocks
# themselves: its secondary allocator maps every block above 128 KB.)
# The library is made first, alone (check-asan-lib): the fuzz driver links it too, and make
# check runs the fuzz slice beside these tests, not after them.
# ($(MAKE) written out in the recipes: a make reached through another variable gets no jobserver)
ASAN_BUILD = --no-print-directory BUILD=build/asan EXTRA_CFLAGS="$(SAN_FLAGS)"
check-asan-lib: deps
	@$(MAKE) $(ASAN_BUILD) lib
check-asan: check-asan-lib
	$(MAKE) $(ASAN_BUILD) ASAN_OPTIONS=detect_leaks=1:clear_shadow_mmap_threshold=1073741824 UBSAN_OPTIONS=halt_on_error=1 \
	  CK_TIMEOUT_MULTIPLIER=15 KERNEL_RUNS=no check-c

# under FreeCAD's Python and under the python3 first on PATH (when it is another one). make check
# runs the two side by side (its -j): each has a temporary directory of its own (--basetemp,
# emptied at its start) rather than both numbering theirs in /tmp/pytest-of-<user>, which every
# pytest on the machine shares, and writes its output to a log of its own ($(BUILD)/pytest-*.log),
# printed whole when the run fails and by its last line (the counts) when it passes.
# The python3 on PATH leaves out the tests marked c_numerics (tests/python/conftest.py: they
# assert the C library's numbers through binding calls that the other tests make under both
# Pythons; FreeCAD's Python runs them): its summary counts them as deselected.
# Each log lists its 30 slowest tests (--durations: where make check's time goes, read without
# another run).
# $(call pytest-run,PYTHON,NAME[,OPTIONS]): one shell command; PYTEST_ARGS: more options
pytest-run = { log=$(CURDIR)/$(BUILD)/pytest-$(2).log; \
	echo "== pytest under $$(command -v $(1)) (log $(BUILD)/pytest-$(2).log)"; \
	cd tests/python && LIBELASTICA_PATH=$(CURDIR)/$(BUILD)/libelastica.so PYTHONPATH=$(CURDIR)/python \
	  $(1) -m pytest -q -p no:cacheprovider --strict-markers --basetemp=$(CURDIR)/$(BUILD)/pytest-$(2) --durations=30 $(3) $(PYTEST_ARGS) . \
	  > $$log 2>&1 || { cat $$log; echo "FAILED: pytest under $(1) (log $(BUILD)/pytest-$(2).log)"; exit 1; }; \
	tail -n 1 $$log; }
check-python: check-python-sys check-python-path
check-python-sys: lib
	@$(call pytest-run,$(SYSPYTHON),sys)
check-python-path: lib
	@if [ "$$(command -v $(PYTHON))" != "$(SYSPYTHON)" ]; then $(call pytest-run,$(PYTHON),path,-m "not c_numerics"); fi

# FreeCAD's tests (in FC_GROUPS freecadcmd processes, one after another: freecad.mk), its GUI smoke (a HOME of its own:
# freecad.mk) and the addon check are jobs of make's -j: the smoke runs beside the tests
# where a job slot is free, never as a process beyond CHECK_JOBS (the tests and the smoke
# have wall-clock limits: started as a third process beside them at load 15, both ran out).
check-freecad: lib
	@if [ -d tests/freecad ] && ls tests/freecad/test_*.py >/dev/null 2>&1; then \
	  $(MAKE) --no-print-directory -f tests/freecad/freecad.mk BUILD=$(BUILD); fi

# The stages are independent once the library is built: make check runs them CHECK_JOBS (the
# cores) at a time, each stage's output printed whole when it ends (-Otarget). It is CPU-bound
# (~37 CPU-min, 19 min on 2 cores at df9a38e: as long as the cores are kept busy, the order changes little), so
# the longest single processes start first: the pytest run under FreeCAD's Python (~6 CPU-min),
# FreeCAD's tests (~3.5 min, FC_GROUPS freecadcmd processes one after another; its GUI smoke, ~3 min, beside them
# when a slot is free), then the other pytest run, and the ~100 short C test runs fill the
# cores after them, so that no long stage runs alone at the end (FreeCAD's chain, once listed
# after both pytest runs, started ~8 min in and ran 6 min, tests then smoke). The fuzz slice
# needs only build/asan's library (check-asan-lib, made once: two makes building it at once
# would race), not the ASan tests' end.
CHECK_JOBS ?= $(shell nproc 2>/dev/null || echo 2)
check: deps
	@$(MAKE) --no-print-directory -j$(CHECK_JOBS) -Otarget check-stages
	@echo "make check: all tests passed"

check-stages: lib check-python-sys check-freecad check-python-path check-asan check-fuzz-stage check-c check-tsan \
              check-install
check-fuzz-stage: check-asan-lib lib
	@$(MAKE) --no-print-directory check-fuzz

# ------------------------------------------------------------------ fuzzing, ThreadSanitizer

# fuzz/: the harness (fuzz.c, one ENTRY per public function in entries.def), the
# adversarial driver (cc, ASan + UBSan) and the libFuzzer target (clang). clang
# and its runtime (libFuzzer) are installed by the targets that need them.
FUZZ_PKGS  := clang libclang-rt-14-dev
# No -O here: the sanitized objects keep the plain build's -O2 (-O3 on the fit's hot path).
# ASan asks for -O1 or more (an access the optimiser removes is not checked, at -O1 too); the
# sanitized fit tests run 1.6 x faster than at -O1 (test_fit_nearest 19.6 -> 12.3 CPU-s,
# 1.7 x its plain run).
SAN_FLAGS  := -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_SRC   := fuzz/fuzz.c fuzz/entries.c
FUZZ_DEPS  := $(FUZZ_SRC) fuzz/fuzz.h fuzz/entries.def libelastica/binding.h
FUZZ_ENV   := ASAN_OPTIONS=allocator_may_return_null=1:detect_leaks=1 \
              LSAN_OPTIONS=suppressions=$(CURDIR)/fuzz/lsan-suppressions \
              UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# clang 14 takes minutes over bspline_approx_fit.c's unrolled loops with pointer-overflow checks:
# the libFuzzer build leaves those to the driver's gcc build
CLANG_SAN  := -fno-sanitize=pointer-overflow
FUZZ_SLICE ?= 0.1
FUZZ_SCALE ?= 1
FUZZ_SECONDS ?= 600

fuzz-deps:
	$(call apt-install,$(FUZZ_PKGS))

build/fuzz/driver: fuzz/driver.c $(FUZZ_DEPS) $(LIB_SRC) include/elastica.h libelastica/internal.h | deps
	@$(MAKE) --no-print-directory BUILD=build/asan EXTRA_CFLAGS="$(SAN_FLAGS)" build/asan/libelastica.a
	@mkdir -p build/fuzz
	$(CC) $(CFLAGS_BASE) $(SAN_FLAGS) $(DEPS_CFLAGS) fuzz/driver.c $(FUZZ_SRC) -o $@ \
	  build/asan/libelastica.a $(DEPS_LIBS)

# the same driver without sanitizers: times a call that is slow under them at full speed
build/fuzz/driver-release: fuzz/driver.c $(FUZZ_DEPS) $(BUILD)/libelastica.a
	@mkdir -p build/fuzz
	$(CC) $(CFLAGS_BASE) $(DEPS_CFLAGS) fuzz/driver.c $(FUZZ_SRC) -o $@ $(BUILD)/libelastica.a $(DEPS_LIBS)

build/fuzz/libfuzzer: fuzz/libfuzzer.c $(FUZZ_DEPS) $(LIB_SRC) include/elastica.h libelastica/internal.h | deps fuzz-deps
	@$(MAKE) --no-print-directory BUILD=build/libfuzzer CC=clang \
	  EXTRA_CFLAGS="$(SAN_FLAGS) $(CLANG_SAN) -fsanitize=fuzzer-no-link" build/libfuzzer/libelastica.a
	@mkdir -p build/fuzz
	clang $(CFLAGS_BASE) $(SAN_FLAGS) $(CLANG_SAN) -fsanitize=fuzzer $(DEPS_CFLAGS) fuzz/libfuzzer.c $(FUZZ_SRC) -o $@ \
	  build/libfuzzer/libelastica.a $(DEPS_LIBS)

# every function of the header must have its ENTRY (README, Architecture: how to add one),
# and every one of libelastica/binding.h (the binding's entry: not public, exported all the same)
fuzz-coverage:
	@hdr=$$(sed -n 's/^[a-z][a-z_ ]*[ *]\(el_[a-z0-9_]*\)(.*/\1/p' include/elastica.h libelastica/binding.h | sort -u); \
	ent=$$(sed -n 's/^ENTRY(\(el_[a-z0-9_]*\),.*/\1/p' fuzz/entries.def | sort -u); \
	missing=$$(for f in $$hdr; do echo "$$ent" | grep -qx "$$f" || echo "$$f"; done); \
	if [ -n "$$missing" ]; then \
	  echo "fuzz: functions of elastica.h / binding.h without an ENTRY in fuzz/entries.def:" $$missing; exit 1; fi

# make check: a deterministic slice (<= 60 s) and the corpus of past findings,
# tolerating only fuzz/known-findings (other owners' open issues)
FUZZ_RELEASE := --release build/fuzz/driver-release

check-fuzz: build/fuzz/driver build/fuzz/driver-release fuzz-coverage
	@rm -rf build/fuzz/findings && mkdir -p build/fuzz/findings
	$(FUZZ_ENV) build/fuzz/driver --known fuzz/known-findings $(FUZZ_RELEASE) --scale $(FUZZ_SLICE)
	$(FUZZ_ENV) build/fuzz/driver --known fuzz/known-findings $(FUZZ_RELEASE) --replay fuzz/corpus

# the whole driver, then libFuzzer for FUZZ_SECONDS; the last line sums both. Findings
# of fuzz/known-findings (other owners' open issues) are counted apart, as "known".
# Slow calls are the driver's to judge (CPU time, known list): libFuzzer's wall-clock
# "slow units" on a shared machine are not findings; its timeouts (20 s) are.
fuzz: build/fuzz/driver build/fuzz/driver-release build/fuzz/libfuzzer fuzz-coverage
	@rm -rf build/fuzz/findings build/fuzz/work && mkdir -p build/fuzz/findings build/fuzz/work
	@build/fuzz/driver --write-seeds build/fuzz/work
	@set +e; $(FUZZ_ENV) build/fuzz/driver --known fuzz/known-findings $(FUZZ_RELEASE) --scale $(FUZZ_SCALE) \
	  | tee build/fuzz/driver.log; \
	$(FUZZ_ENV) build/fuzz/driver --known fuzz/known-findings $(FUZZ_RELEASE) --replay fuzz/corpus \
	  | tee -a build/fuzz/driver.log; \
	$(FUZZ_ENV) FUZZ_KNOWN=fuzz/known-findings build/fuzz/libfuzzer -max_total_time=$(FUZZ_SECONDS) \
	  -timeout=20 -report_slow_units=60 -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
	  -artifact_prefix=build/fuzz/findings/ build/fuzz/work fuzz/corpus > build/fuzz/libfuzzer.log 2>&1; \
	grep -E "^FINDING|ERROR|^libfuzzer:|Done [0-9]+ runs" build/fuzz/libfuzzer.log; \
	sum() { sed -n "s/$$1/\1/p" $$2 | awk '{s+=$$1} END {print s+0}'; }; \
	d=$$(sum '^fuzz driver: \([0-9]*\) inputs.*' build/fuzz/driver.log); \
	df=$$(sum '^fuzz driver: .*findings: \([0-9]*\)$$' build/fuzz/driver.log); \
	dk=$$(sum '^fuzz driver: \([0-9]*\) findings of.*' build/fuzz/driver.log); \
	l=$$(sum '^stat::number_of_executed_units: *\([0-9]*\)' build/fuzz/libfuzzer.log); \
	lk=$$(sum '^libfuzzer: \([0-9]*\) findings of.*' build/fuzz/libfuzzer.log); \
	lf=$$(ls build/fuzz/findings | grep -cE '^(crash|leak|timeout|oom)-'); \
	echo "make fuzz: $$((d + l)) inputs (driver $$d, libFuzzer $$l in $(FUZZ_SECONDS) s), findings: $$((df + lf))" \
	  "(known, fuzz/known-findings: $$((dk + lk)))"; \
	[ $$((df + lf)) -eq 0 ]

# evaluation, Hermite, B-splines, blends and resampling called from 4 threads at once
check-tsan: | deps
	@$(MAKE) --no-print-directory BUILD=build/tsan EXTRA_CFLAGS="-O1 -g -fsanitize=thread" build/tsan/libelastica.a
	$(CC) $(CFLAGS_BASE) -O1 -g -fsanitize=thread $(DEPS_CFLAGS) tests/tsan/test_concurrent.c \
	  -o build/tsan/test_concurrent build/tsan/libelastica.a $(DEPS_LIBS)
	TSAN_OPTIONS=halt_on_error=1:exitcode=66 build/tsan/test_concurrent

# ------------------------------------------------------------------ bench, demo, install

$(BUILD)/bench/%: bench/%.c $(wildcard bench/*.h) $(BUILD)/libelastica.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_BASE) $(DEPS_CFLAGS) $< -o $@ $(BUILD)/libelastica.a $(DEPS_LIBS)

# OpenCASCADE's FairCurve_Batten, the comparison of bench_hermite_occt.cc (C++), from
# Debian's development packages: installed by `make bench` only.
OCCT_PKGS := libocct-modeling-algorithms-dev libocct-modeling-data-dev
OCCT_LIBS := -lTKGeomAlgo -lTKGeomBase -lTKG2d -lTKMath -lTKernel
occt-dev:
	$(call apt-install,$(OCCT_PKGS))

# libspiro, the comparison of bench_spline.c (Debian's libspiro-dev): installed by `make bench` only.
SPIRO_PKGS := libspiro-dev
spiro-dev:
	$(call apt-install,$(SPIRO_PKGS))

$(BUILD)/bench/bench_spline: bench/bench_spline.c $(BUILD)/libelastica.a | spiro-dev
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_BASE) $(DEPS_CFLAGS) $< -o $@ $(BUILD)/libelastica.a $(DEPS_LIBS) -lspiro

$(BUILD)/bench/%: bench/%.cc $(BUILD)/libelastica.a | occt-dev
	@mkdir -p $(dir $@)
	$(CXX) -O2 -Wall -Iinclude -I/usr/include/opencascade -Wno-deprecated-declarations $< -o $@ \
	  $(BUILD)/libelastica.a $(DEPS_LIBS) $(OCCT_LIBS)

# comparison packages for the benchmarks only (PyPI), into the python3 on PATH.
# OPENBLAS_NUM_THREADS=1: Ipopt's BLAS would otherwise spin idle worker threads on
# problems this small (~9 % of a Hermite profile), charging every figure for them.
BENCH_PIP := clothoids scipy
# Every line is kept in $(BUILD)/bench.jsonl; the lines with "readme" and "value" keys
# become the README's figures table (bench/readme_figures.py): one source of truth. A
# bench that fails is named, its figures are left out of the table, and make bench fails.
bench: all $(BENCH_BIN) $(BENCH_CXX_BIN)
	@$(PYTHON) -c "import Clothoids, scipy" 2>/dev/null || $(PYTHON) -m pip install -q $(BENCH_PIP)
	@rm -f $(BUILD)/bench.failed
	@{ for b in $(BENCH_BIN) $(BENCH_CXX_BIN); do OPENBLAS_NUM_THREADS=1 $$b || echo $$b >> $(BUILD)/bench.failed; done; \
	  for b in bench/bench_*.py; do [ -f "$$b" ] || continue; \
	    OPENBLAS_NUM_THREADS=1 LIBELASTICA_PATH=$(CURDIR)/$(BUILD)/libelastica.so \
	    PYTHONPATH=$(CURDIR)/python $(PYTHON) $$b || echo $$b >> $(BUILD)/bench.failed; done; } | tee $(BUILD)/bench.jsonl
	@$(PYTHON) bench/readme_figures.py $(BUILD)/bench.jsonl README.md
	@if [ -s $(BUILD)/bench.failed ]; then echo "make bench: failed (their figures left out):" $$(cat $(BUILD)/bench.failed); exit 1; fi

# Every tension-mode solution of random problems solved again by its length (bench/sets/
# length_recovers_tension.c, 3 x 20 000 problems, ~75 s): prints those the length mode
# misses, a completeness check of speed changes to it beside hermite-sets.
length-recovers: $(BUILD)/libelastica.a
	$(CC) $(CFLAGS_BASE) $(DEPS_CFLAGS) bench/sets/length_recovers_tension.c -o $(BUILD)/length-recovers \
	  $(BUILD)/libelastica.a $(DEPS_LIBS)
	@for s in 31337 777 4242; do $(BUILD)/length-recovers 6 20000 $$s; done

# The Hermite solution sets of this tree and of git revision OLD on 8 x 1000 fixed problems
# (bench/sets/): a speed change to the solver must keep every solution (issue 16). Fails
# when a solution of OLD's is lost; prints the problems that lost or gained one.
SETS_DIR = $(BUILD)/hermite-sets
hermite-sets: $(BUILD)/libelastica.a
	@test -n "$(OLD)" || { echo "make hermite-sets: name the build to compare with, OLD=<git revision>"; exit 1; }
	@rm -rf $(SETS_DIR) && mkdir -p $(SETS_DIR)/old
	git archive $(OLD) | tar -x -C $(SETS_DIR)/old
	$(MAKE) --no-print-directory -C $(SETS_DIR)/old BUILD=build build/libelastica.a
	$(CC) -I$(SETS_DIR)/old/include $(CFLAGS_BASE) $(DEPS_CFLAGS) bench/sets/hermite_sets.c -o $(SETS_DIR)/dump-old \
	  $(SETS_DIR)/old/build/libelastica.a $(DEPS_LIBS)
	$(CC) $(CFLAGS_BASE) $(DEPS_CFLAGS) bench/sets/hermite_sets.c -o $(SETS_DIR)/dump-new $(BUILD)/libelastica.a $(DEPS_LIBS)
	$(SETS_DIR)/dump-old > $(SETS_DIR)/old.txt
	$(SETS_DIR)/dump-new > $(SETS_DIR)/new.txt
	$(PYTHON) bench/sets/compare_sets.py $(SETS_DIR)/old.txt $(SETS_DIR)/new.txt

# headless FreeCAD (freecadcmd) with a throw-away HOME; the report is printed, the full log kept
demo: all
	@rm -rf $(BUILD)/demo-home && mkdir -p $(BUILD)/demo-home out
	@rc=0; HOME=$(CURDIR)/$(BUILD)/demo-home LIBELASTICA_PATH=$(CURDIR)/$(BUILD)/libelastica.so \
	  PYTHONPATH=$(CURDIR)/python ELASTICA_DEMO_OUT=$(CURDIR)/out \
	  freecadcmd $(CURDIR)/examples/demo.py > $(BUILD)/demo.log 2>&1 || rc=$$?; \
	sed -n '/^libelastica demo/,$$p' $(BUILD)/demo.log; \
	if [ $$rc -ne 0 ]; then cat $(BUILD)/demo.log; echo "make demo: FAILED (log $(BUILD)/demo.log)"; exit 1; fi

# the README's pictures, made by the command line on the bundled examples
GALLERY_CLI = LIBELASTICA_PATH=$(CURDIR)/$(BUILD)/libelastica.so PYTHONPATH=$(CURDIR)/python $(SYSPYTHON) -m libelastica
gallery: all
	@mkdir -p docs/gallery
	$(GALLERY_CLI) fit examples/keyline_3d.csv --keyline --model smooth --png docs/gallery/keyline_3d.png
	$(GALLERY_CLI) fit examples/sample_2d.csv --png docs/gallery/fit_2d.png
	$(GALLERY_CLI) hermite 0 0 0 1 2 0 0 -1 --length 4 --png docs/gallery/hermite.png
	$(GALLERY_CLI) blend 0 0 0.3 0.8 0.7 0.9 1 0 --m 0.3 --png docs/gallery/blend.png
	$(GALLERY_CLI) fit examples/sample_s_curve.csv --model smooth --json $(BUILD)/s_curve_fit.json > /dev/null
	$(GALLERY_CLI) g2quad $(BUILD)/s_curve_fit.json --edges 24 --png docs/gallery/g2quad.png
	@$(MAKE) --no-print-directory -f tests/freecad/freecad.mk BUILD=$(BUILD) fc-gallery

# the workbench into FreeCAD's user Mod folder (made if missing) as a link to this tree
FREECAD_MOD ?= $(HOME)/.local/share/FreeCAD/Mod
freecad-install: lib
	@mkdir -p "$(FREECAD_MOD)"
	@if [ -e "$(FREECAD_MOD)/elastica" ] && [ ! -L "$(FREECAD_MOD)/elastica" ]; then \
	  echo "make freecad-install: $(FREECAD_MOD)/elastica exists and is not a link; remove it first"; \
	  exit 1; fi
	@ln -sfn "$(CURDIR)/freecad_wb" "$(FREECAD_MOD)/elastica"
	@echo "Elastica workbench: $(FREECAD_MOD)/elastica -> $(CURDIR)/freecad_wb (library $(BUILD)/libelastica.so);"
	@echo "restart FreeCAD and pick the Elastica workbench"

install: lib
	install -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include
	install -m 644 include/elastica.h $(BUILD)/include/elastica_abi.h $(DESTDIR)$(PREFIX)/include/
	install -m 755 $(BUILD)/libelastica.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/
	ln -sf libelastica.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libelastica.so
	install -m 644 $(BUILD)/libelastica.a $(DESTDIR)$(PREFIX)/lib/
	printf 'prefix=%s\nlibdir=$${prefix}/lib\nincludedir=$${prefix}/include\n\nName: elastica\nDescription: %s\nVersion: %s\nRequires.private: gsl ipopt\nLibs: -L$${libdir} -lelastica\nCflags: -I$${includedir}\n' \
	  '$(PREFIX)' 'Euler elastica for CAD: evaluation, fairing, Hermite, B-splines' '$(VERSION)' \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/elastica.pc
	@echo "installed into $(DESTDIR)$(PREFIX)"

# install into a staging prefix and build the README's C example against it with pkg-config
check-install: lib
	rm -rf $(BUILD)/stage
	$(MAKE) --no-print-directory install PREFIX=$(CURDIR)/$(BUILD)/stage
	PKG_CONFIG_PATH=$(BUILD)/stage/lib/pkgconfig $(CC) -std=c99 -Wall -Werror examples/readme_example.c \
	  $$(PKG_CONFIG_PATH=$(BUILD)/stage/lib/pkgconfig pkg-config --cflags --libs elastica) -o $(BUILD)/readme_example
	LD_LIBRARY_PATH=$(BUILD)/stage/lib $(BUILD)/readme_example
	@v=$$(PKG_CONFIG_PATH=$(BUILD)/stage/lib/pkgconfig pkg-config --modversion elastica); \
	if [ -z "$(VERSION)" ] || [ "$$v" != "$(VERSION)" ]; then \
	  echo "check-install: pkg-config says version '$$v', the header's EL_VERSION_STRING '$(VERSION)'"; exit 1; fi
	@# the installed shared library exports the API only (el_ and a letter), so no
	@# function of a program that uses it can replace one of the library's own; the
	@# static one defines no name outside el_* (its internals el__*)
	@so=$$(nm -D --defined-only $(BUILD)/stage/lib/libelastica.so | awk '{print $$3}' | grep -v '^el_[a-z]' || true); \
	a=$$(nm -g --defined-only $(BUILD)/stage/lib/libelastica.a | awk 'NF == 3 {print $$3}' | grep -v '^el_' || true); \
	if [ -n "$$so$$a" ]; then echo "check-install: symbols outside the library's names:" $$so $$a; exit 1; fi
	@echo "check-install: libelastica.so exports $$(nm -D --defined-only $(BUILD)/stage/lib/libelastica.so | grep -c ' el_') symbols, all el_*"

clean:
	rm -rf build build-* out
