# pdq: the two commands of the README, and the rest of the workflow.
#   make run    install missing Debian packages, build, run the flagship example
#   make test   the same, then the whole suite (MPI tests at 1-4 ranks, LAMMPS, ParaView)
#   make fuzz   the libFuzzer targets of fuzz/ (clang), FUZZ_SECONDS each
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

# The suite includes a short fuzz run (tests/fuzz/), which needs clang (deps-test has it).
test: CMAKE_FLAGS += -DPDQ_FUZZ_TARGETS=ON
# One test more than cores: many tests spend much of their time waiting on the processes
# they start (signals, watchdogs, mpirun start-up).
test: deps-test build
	cd $(BUILD) && ctest --output-on-failure -j$$(( $(JOBS) + 1 )) --timeout 900

# The fuzz targets as the suite builds them (tests/fuzz/), each run FUZZ_SECONDS.
fuzz:
	@bash tools/install-deps.sh fuzz
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DPDQ_FUZZ_TARGETS=ON >/dev/null
	@cmake --build $(BUILD) -j$(JOBS) --target pdq_fuzz_targets
	FUZZ_BIN=$(BUILD)/tests/fuzz/build FUZZ_OUT=$(BUILD)/fuzz-findings \
	  bash tools/fuzz.sh $(or $(FUZZ_SECONDS),600)

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
