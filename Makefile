# fpmshell: the two everyday commands are `make run` and `make test` (README.md).
#   make run       install missing Debian packages, build, run the example, plot its histories
#   make test      install missing Debian packages, build, run the tests (slow validation excluded)
#   make validate  build, run the slow validation problems, write the validation report
#   make bench     build with benchmarks and run them
#   make fuzz      fuzz every reader for FUZZ_SECONDS (default 60) each, sanitizers on (clang)
#   make sanitize  build with AddressSanitizer + UBSan, run the unit and io tests and the examples
#   make tsan      build with ThreadSanitizer (clang), run the unit tests and the examples on 2 threads
#   make format    lay out every C++ file as .clang-format says (make test checks it)
#   make picture   run the square tube (coarse, mass-scaled, ~5 min) and draw the README's picture
#   make clean     remove the build folder

BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
# The Debian python3-numpy / python3-matplotlib packages belong to /usr/bin/python3; a python3
# found earlier on PATH (pyenv, conda) may lack them.
PYTHON  ?= $(shell test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)
EXAMPLE ?= examples/spherical_cap_elastic
RESULTS ?= results/spherical_cap_elastic

# Prerequisites run in the order written (dependencies, then configure, then build).
.NOTPARALLEL:
.PHONY: run test validate bench fuzz sanitize tsan format picture clean deps configure build

run: deps build
	$(BUILD)/fpmshell run $(EXAMPLE)/model.yaml -o $(RESULTS) --overwrite
	$(PYTHON) tools/plot_history.py $(RESULTS)
	@echo
	@echo "Results are in $(RESULTS)/:"
	@echo "  history.csv, energy.csv  time histories (plotted by tools/plot_history.py)"
	@echo "  fields.pvd               open in ParaView for the deformed shape and fields"
	@echo "  summary.json, log.txt    run summary and what the run printed"

test: deps build
	ctest --test-dir $(BUILD) --output-on-failure -LE validation -j2

# The report is written even when a problem fails; the target then fails with ctest's status.
validate: build
	ctest --test-dir $(BUILD) -L validation --output-on-failure -j$(JOBS); status=$$?; \
	$(PYTHON) tools/make_validation.py --build $(BUILD) && exit $$status

bench: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DFPMSHELL_BENCHMARKS=ON
	cmake --build $(BUILD) -j$(JOBS)
	$(BUILD)/bench/fpmshell_bench

fuzz: deps
	FUZZ_SECONDS=$(or $(FUZZ_SECONDS),60) FUZZ_JOBS=$(JOBS) scripts/fuzz.sh

sanitize: deps
	JOBS=$(JOBS) scripts/sanitize.sh

tsan: deps
	JOBS=$(JOBS) scripts/tsan.sh

# The README's picture and plot (docs/images/): the square tube of examples/square_tube on its
# coarse mesh with the example's commented mass scaling on, its last frame and its block force.
PICTURE_RUN ?= results/square_tube_picture
picture: deps build
	mkdir -p $(PICTURE_RUN) docs/images
	sed 's|^  # mass_scaling:|  mass_scaling:|' examples/square_tube/model.yaml > $(PICTURE_RUN)/model.yaml
	$(BUILD)/fpmshell run $(PICTURE_RUN)/model.yaml -o $(PICTURE_RUN)/results --overwrite --quiet \
	    --set mesh.divisions_width=15 --set mesh.divisions_length=64
	$(PYTHON) tools/render_picture.py $(PICTURE_RUN)/results docs/images/square_tube.png --mirror xy \
	    --plot docs/images/square_tube_force.png --x striker_uz --y striker_force \
	    --x-scale -1000 --y-scale 0.004 --x-label "crush (mm)" --y-label "block force (kN)"

format: deps
	git ls-files '*.cpp' '*.hpp' | grep -E '^(src|app|tests|bench|fuzz)/' | xargs clang-format -i

deps:
	@scripts/install-deps.sh

configure:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j$(JOBS)

clean:
	rm -rf $(BUILD)
