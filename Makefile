# mistfall — top-level commands. `make demo` and `make test` install what is missing and build first.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CASE ?= cases/dam_break.toml
OUT ?= out/demo

.PHONY: deps build test demo bench validate clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS) -- --no-print-directory

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

demo: build
	@rm -rf $(OUT)
	$(BUILD_DIR)/mistfall simulate $(CASE) --out $(OUT)
	@echo "demo: frames in $(OUT)/frames (open $(OUT)/frames.pvd in ParaView), diagnostics in $(OUT)/diagnostics.csv"

bench: build
	@bench/run_benchmarks.sh $(BUILD_DIR)

validate: build
	@tools/validate.sh $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR)
