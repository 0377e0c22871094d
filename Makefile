# tactus: `make demo` and `make test` each do the whole set-up on a fresh Debian 12 machine.
BUILD := build/release
JOBS ?= $(shell nproc)
AMEN := /usr/share/sonic-pi/samples/loop_amen_full.flac
TACTUS := $(BUILD)/apps/tactus/tactus

.PHONY: setup build demo test eval format clean

setup:
	bash scripts/setup.sh

build: setup
	cmake --preset release -DTACTUS_BUILD_TESTS=ON
	cmake --build --preset release -j $(JOBS)

demo: build
	mkdir -p out
	$(TACTUS) render $(AMEN) -o out/amen.vibration.wav --force
	$(TACTUS) analyze $(AMEN) -o out/amen.features.csv --force

test: build
	ctest --preset release -j $(JOBS)

eval: build
	/usr/bin/python3 eval/evaluate.py $(BUILD) --out eval/results.md

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf build out
