# MixEngine — the two set-up commands of the README, plus helpers.
#   make demo   install, build, slice a generated 20 mm cube -> out/demo.gcode
#   make test   install, build, run every test
BUILD ?= build
JOBS ?= 2

.PHONY: install build demo test unit pytests format bench clean

install:
	./install.sh

build: install
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	@mkdir -p out
	./$(BUILD)/mixengine demo out

unit: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

pytests: build
	tests/python/run.sh $(BUILD)

test: unit pytests

format:
	find engine tests -name '*.cpp' -o -name '*.h' | xargs clang-format -i

bench: build
	tests/bench/run.sh $(BUILD)
	tests/bench/quality.sh $(BUILD)

clean:
	rm -rf $(BUILD) out
