# tactus: `make demo` and `make test` each do the whole set-up on a fresh Debian 12 machine.
BUILD := build/release
JOBS ?= $(shell nproc)
AMEN := /usr/share/sonic-pi/samples/loop_amen_full.flac
TACTUS := $(BUILD)/bin/tactus

.PHONY: setup build demo test test-asan test-tsan fuzz eval bench bench-compare bench-instructions format format-check tidy clean

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

# Every test but realtime_tests (ASan owns malloc) again under AddressSanitizer +
# UndefinedBehaviorSanitizer (build/asan).
test-asan: setup
	cmake --preset asan
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS)

# The tests labelled `threads` (engine, live front end, tactus~ in pd, the plugin in its hosts)
# under ThreadSanitizer (build/tsan): only the targets they need are built. pd and Ardour's VST3
# scanner, not instrumented, run with the TSan runtime preloaded. Races inside Debian's libraries
# are suppressed in tsan.supp; the tests that replace malloc are left out (TSan owns it).
test-tsan: setup
	cmake --preset tsan
	cmake --build --preset tsan -j $(JOBS)
	ctest --preset tsan -j $(JOBS)

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
# audio second, a structural swap (bench/instructions.sh).
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
# the release configure's compile_commands.json; clang does not know GCC's -fno-fat-lto-objects.
TIDY_FILES := ^$(CURDIR)/(src|apps|fuzz|bench)/
tidy: $(BUILD)/compile_commands.json
	run-clang-tidy -j $(JOBS) -quiet -p $(BUILD) -header-filter='$(TIDY_FILES)' \
	  -extra-arg=-Wno-ignored-optimization-argument '$(TIDY_FILES)'

$(BUILD)/compile_commands.json:
	$(MAKE) setup
	cmake --preset release -DTACTUS_BUILD_TESTS=ON

clean:
	rm -rf build out
