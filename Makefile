# mistfall — top-level commands. `make demo` and `make test` install what is missing and build first.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CASE ?= cases/dam_break.toml
OUT ?= out/demo

PREFIX ?= /usr/local

.PHONY: deps build test install demo demo-render bench validate clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS) -- --no-print-directory

test: build
	@# Tests run in parallel (ctest -j): one OpenMP thread each unless a test sets its own, and passive waiting,
	@# so threads never spin against each other on a small machine.
	@cd $(BUILD_DIR) && OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive ctest --output-on-failure -j $(JOBS)

# PREFIX/bin/mistfall, PREFIX/share/mistfall/{render,cases}, PREFIX/share/doc/mistfall (make install PREFIX=~/.local).
install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX)

# The whole pipeline on the waterfall (mistfall run: simulate with inline classification, texture, render) over
# the paper's whole 8.5 s, rendered every 0.1 s (86 frames, render.frame_interval), and a contact sheet of the
# paper's Fig. 6/7 instants t/T = 76, 77 and 85 of 85 (docs/render.md). Measured on the idle 2-core machine: 11 min
# 19 s (simulate 6.6 min, texture 1.1, render 3.3), 697 MB; set DEMO_UNTIL=0.8 for a quick look (the contact sheet
# then has no frames).
DEMO_CASE ?= cases/waterfall_small.toml
DEMO_UNTIL ?= 8.5
demo: build
	@rm -rf $(OUT)
	$(BUILD_DIR)/mistfall run $(DEMO_CASE) --out $(OUT) --until $(DEMO_UNTIL)
	@cp $(OUT)/render/*.mp4 $(OUT)/waterfall.mp4
	@cp $(OUT)/render/*.gif $(OUT)/waterfall.gif
	@scripts/contact_sheet.sh $(OUT) $(OUT)/contact_sheet.png "7.6:t/T = 76/85" "7.7:t/T = 77/85" "8.5:t/T = 85/85"
	@echo "demo: $(OUT)/waterfall.mp4, .gif and (when the run reached 8.5 s) contact_sheet.png, frames in $(OUT)/render/png, particles in $(OUT)/frames (frames.pvd for ParaView)"

# The whole pipeline on the default case: simulate, render (mistfall run; the dam break writes no flow fields, so
# the texture stage is skipped). About 7 minutes on 2 cores, 0.7 GB of meshes and images in out/demo-render.
demo-render: build
	@rm -rf $(OUT)-render
	$(BUILD_DIR)/mistfall run $(CASE) --out $(OUT)-render
	@echo "demo-render: images in $(OUT)-render/render/png, animation $(OUT)-render/render/*.mp4 and .gif"

bench: build
	@bench/run_benchmarks.sh $(BUILD_DIR)

validate: build
	@tools/validate.sh $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR)
