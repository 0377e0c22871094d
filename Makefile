# tactus: `make demo` and `make test` each do the whole set-up on a fresh Debian 12 machine.
BUILD := build/release
JOBS ?= $(shell nproc)
AMEN := /usr/share/sonic-pi/samples/loop_amen_full.flac
TACTUS := $(BUILD)/bin/tactus

.PHONY: setup build demo test test-asan test-tsan test-arm test-arm64 test-armhf setup-arm fuzz eval bench bench-compare bench-instructions format format-check tidy clean

setup:
	bash scripts/setup.sh

# The build also lets /usr/bin/python3 import tactus from it (a tactus.pth in the user's
# site-packages, apps/python/use_build_tree.sh).
build: setup
	cmake --preset release -DTACTUS_BUILD_TESTS=ON
	cmake --build --preset release -j $(JOBS)
	if [ -d $(BUILD)/python/tactus ]; then \
	  bash apps/python/use_build_tree.sh /usr/bin/python3 $(BUILD)/python; fi

demo: build
	mkdir -p out
	$(TACTUS) render $(AMEN) -o out/amen.vibration.wav --actuator voice-coil --force
	$(TACTUS) analyze $(AMEN) -o out/amen.features.csv --actuator voice-coil --force
	$(TACTUS) meter out/amen.vibration.wav -o out/amen.meter.csv --force
	$(TACTUS) render $(AMEN) -o out/amen.four-channel.wav --preset four-channel --actuator voice-coil --force
	$(TACTUS) meter out/amen.four-channel.wav

test: build
	ctest --preset release -j $(JOBS)

# Every test but realtime_tests (ASan owns malloc) and the pages in Chromium again under
# AddressSanitizer + UndefinedBehaviorSanitizer (build/asan), at -O1 with line tables only (-g1):
# reports keep their files and lines, and a file compiles 2.5 times faster than at -O2 -g
# (export_test.cpp: 24 s against 58 s). The pages' tests (report.chromium 122 s, studio.chromium
# 170 s, run alone, of the 445 s the tests took) test the pages' script; the C++ they drive runs in
# report.meters_beside_the_render, the Cli tests and fuzz_replay_studio (the request handler).
test-asan: setup
	cmake --preset asan
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS)

# The tests labelled `threads` (engine, live front end, tactus~ in pd, the plugin in its hosts)
# under ThreadSanitizer (build/tsan), -O2 with line tables only (at -O1 the tests run slower than
# the build gains, and the live tests miss more periods): only the targets they need are built.
# pd and Ardour's VST3 scanner, not instrumented, run with the TSan runtime preloaded.
# Races inside Debian's libraries are suppressed in tsan.supp; the tests that replace malloc are
# left out (TSan owns it), and so are those without threads of their own (the preset's filter).
test-tsan: setup
	cmake --preset tsan
	cmake --build --preset tsan -j $(JOBS)
	ctest --preset tsan -j $(JOBS)

# The library, the command line and tactus~ cross-built for arm64 and armhf (build/arm64,
# build/armhf; Debian's cross toolchains, scripts/setup.sh arm) and their tests under qemu-user:
# the unit tests, the engine's, the drum corpus and the Amen break rendered as the x86 release
# build renders it, within 1e-4 (cross.amen_render_as_host). Left out: the tests that run the
# command line or pd as a child process (qemu-user runs one program, not what it executes) and,
# unless ARM_SLOW=1, the threaded front end's and the allocation counters' and the check that the
# analysis reads only the parameters it names (minutes under qemu, no arithmetic of their own),
# and on armhf (qemu-arm twice as slow as qemu-aarch64) the drum corpus's figures and three of the
# engine's four block-size sweeps, which arm64 runs (4 min of the 15 of test time; the whole
# pipeline's arithmetic on armhf is cross.amen_render_as_host's).
ARM_TARGETS := tactus_tests engine_tests realtime_tests end_to_end_tests tactus_cli tactus_pd
ARM_EXCLUDE := ^(Cli|HelperPrograms|BadInput|FullDisk|Interrupted|PdExternal|Sounds/Export)\.|fuzz_replay|^install\.|^report\.|_NOT_BUILT
ARM_SLOW_TESTS := |^(EngineFrontEnd|RealTime)\.|^ReplayAnalysis\.TheAnalysisReadsOnlyTheParametersItNames$$
ARMHF_SLOW_TESTS := |^DrumCorpus\.|^Engine\.(FourChannelBlockSizeInvariance|BlockSizeInvarianceOnDrums|BlockSizeInvarianceWithAnInternalRate)$$
test-arm: test-arm64 test-armhf

test-arm64 test-armhf: test-%: setup-arm
	cmake --preset release -DTACTUS_BUILD_TESTS=ON
	cmake --build --preset release -j $(JOBS) --target tactus_cli
	cmake --preset $*
	cmake --build --preset $* -j $(JOBS) --target $(ARM_TARGETS)
	ctest --test-dir build/$* -j $(JOBS) --output-on-failure --no-tests=error \
	  -E '$(ARM_EXCLUDE)$(if $(ARM_SLOW),,$(ARM_SLOW_TESTS)$(if $(filter armhf,$*),$(ARMHF_SLOW_TESTS)))'

setup-arm:
	bash scripts/setup.sh arm

# Each libFuzzer target for FUZZ_SECONDS (clang; build/fuzz, findings written there).
FUZZ_SECONDS ?= 600
fuzz: setup
	cmake --preset fuzz -DTACTUS_FUZZ_SECONDS=$(FUZZ_SECONDS)
	cmake --build --preset fuzz -j $(JOBS) --target fuzz_targets
	ctest --preset fuzz -j $(JOBS)

eval: build
	/usr/bin/python3 eval/evaluate.py $(BUILD) --out eval/results.md

bench: build
	$(BUILD)/bin/tactus_bench

# Start-up cost in instructions (callgrind): a 10 ms render, Engine::prepare, Engine::process per
# audio second and per 64-frame block, a structural swap (bench/instructions.sh).
bench-instructions: build
	bash bench/instructions.sh $(BUILD)

bench-compare: build
	/usr/bin/python3 bench/compare.py $(BUILD) --out bench/results.md

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

# Fails on any C++ file .clang-format would change (CI runs it first).
format-check: setup
	clang-format --dry-run --Werror $$(git ls-files '*.cpp' '*.hpp')

# clang-tidy (.clang-tidy) on the project's own sources (src/, apps/, fuzz/, bench/; not tests,
# third-party or generated files), any finding an error (CI runs it after format-check). It reads
# the compile_commands.json of the tidy preset (build/tidy: release, each file its own translation
# unit, configured only); clang does not know GCC's -fno-fat-lto-objects.
TIDY_FILES := ^$(CURDIR)/(src|apps|fuzz|bench)/
tidy: setup
	cmake --preset tidy
	run-clang-tidy -j $(JOBS) -quiet -p build/tidy -header-filter='$(TIDY_FILES)' \
	  -extra-arg=-Wno-ignored-optimization-argument '$(TIDY_FILES)'

clean:
	rm -rf build out
