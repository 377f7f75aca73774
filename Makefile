# pdq: the two commands of the README, and the rest of the workflow.
#   make run    install missing Debian packages, build, run the flagship example
#   make test   the same, then the whole suite (MPI tests at 1-4 ranks, LAMMPS, ParaView)
#   make fuzz   the libFuzzer targets of fuzz/ (clang, build-fuzz/), FUZZ_SECONDS each
BUILD ?= build
JOBS ?= $(shell nproc)
PDQ = $(BUILD)/pdq
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps deps-test build run test fuzz bench validate pictures format clean

all: build

deps:
	@bash tools/install-deps.sh build

deps-test:
	@bash tools/install-deps.sh viz

build: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS)

run: build
	bash examples/flagship.sh $(PDQ)

test: deps-test build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 900

fuzz:
	@bash tools/install-deps.sh fuzz
	JOBS=$(JOBS) bash tools/fuzz.sh $(or $(FUZZ_SECONDS),600)

bench: deps-test build
	bash bench/run.sh $(BUILD)

validate: build
	bash bench/mplm/validate.sh $(BUILD)
	bash bench/lab/run.sh $(BUILD)

pictures: build
	bash docs/pictures.sh $(BUILD)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD)
