# MixEngine — the two set-up commands of the README, plus helpers.
#   make demo   install what the engine needs, build the engine alone (no test target), slice a generated 20 mm
#               cube with a colour gradient -> out/demo.gcode
#   make test   install everything, build every target, run every test
#   make engine install what the engine needs, build the engine alone (build/mixengine)
#   make soak   build, then the socket soak (tests/bench/soak.py)
BUILD ?= build
JOBS ?= 2

FUZZ_SECONDS ?= 600
FUZZ_TEST_SECONDS ?= 10

.PHONY: install install-engine engine build demo test unit pytests format bench soak clean fuzz memory plugin plugin-install

install:
	./install.sh

install-engine:
	./install.sh --engine

# One configuration for both (the test targets are configured, MIXENGINE_TESTS): `engine` compiles only the
# mixengine target (no tests/, bench micro or fuzz target), `build` every target.
CONFIGURE = cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null

engine: install-engine
	$(CONFIGURE)
	cmake --build $(BUILD) -j $(JOBS) --target mixengine

build: install
	$(CONFIGURE)
	cmake --build $(BUILD) -j $(JOBS)

demo: engine
	@mkdir -p out
	./$(BUILD)/mixengine demo out

unit: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

pytests: build
	tests/python/run.sh $(BUILD)

# the short fuzz run (tests/fuzz, ~1 min on a fresh clone with 2 cores) and the sanitizer builds of the socket code
# (tests/sanitize/run.sh: ThreadSanitizer socket unit tests, an ASan+UBSan engine under the socket pytests) are part
# of the test flow
test: unit pytests
	tests/fuzz/run.sh $(FUZZ_TEST_SECONDS)
	tests/sanitize/run.sh

format:
	find engine tests -name '*.cpp' -o -name '*.h' | xargs clang-format -i

bench: build
	tests/bench/run.sh $(BUILD)
	tests/bench/quality.sh $(BUILD)

# the socket soak of issue 29 (tests/bench/soak.py): 520 slices through the real libArcus, byte for byte against
# the command line, and 120 early closes (SOAK_ARGS, e.g. --quick or --slices 2000 --seed 7)
soak: build
	tests/bench/soak.sh $(BUILD) $(SOAK_ARGS)

# libFuzzer targets (clang, ASan + UBSan, own build dir build-fuzz), FUZZ_SECONDS per target (10 min each,
# two at a time: about 30 min for the five targets on 2 cores)
fuzz: install
	tests/fuzz/run.sh $(FUZZ_SECONDS)

# peak RSS of MixEngine and CuraEngine 4.13 on a generated 2-million-triangle model
memory: build
	tests/bench/memory.sh $(BUILD)

# Cura 4.13 plugin: $(BUILD)/MixEngine-<version>.curapackage (with the engine), and installing it for this user
plugin: engine
	python3 plugin/package.py --engine $(BUILD)/mixengine --out $(BUILD)

plugin-install: plugin
	python3 plugin/install.py $$(ls -t $(BUILD)/MixEngine-*.curapackage | head -1)

clean:
	rm -rf $(BUILD) out build-asan build-tsan
