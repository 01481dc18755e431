# ARGESIM Comparison 12 — build, test and the reproducible study.
#
#   make test            fpm test of the engine and of the study (installs missing
#                        prerequisites first): the quick suite, each test a few seconds
#   make test-long       the same tests in their deep versions (more cases, longer runs),
#                        300 near-edge rows checked against the replay, and every row of
#                        the collapse grid again at a tenfold smaller vtol (make grid)
#   make replay          ARGS="p=5 e=0.2593": the independent high-precision replay of a
#                        scene (tools/replay, mpmath): separated or collapsed, to 1e-300
#   make test-times      make test, then build/test-times.tsv: every test's wall time
#   make mutants         the mutation check: small bugs, each in a copy, must fail make test;
#                        MECHANICAL=relational,boundary,maxmin (or all) SAMPLE=20 SEED=1:
#                        mutants drawn by rule instead, each group's kill rate (docs/testing.md)
#   make differential    REV=... ARGS="n=2000": the same random rows by a revision and by
#                        the working tree; every finite run must be the same, bit for bit
#   make study           every task's tables, figures and results/summary.md
#   make plot            ARGS="p=30 e=0.6": the space-time diagram of any scene, plot.png
#                        and plot.svg (PLOT=name for another name)
#   make install         the sphere-row CLI, built in release, into $(PREFIX)/bin
#                        (PREFIX ?= ~/.local); make uninstall removes it
#   make check-docs      every number README.md and docs/ quote from results/ against
#                        its table, every relative link, every command they show
#   make test-tools      the tools' own tests (check-docs, make install)
#   make examples        build and run every example program (example/)
#   make bench           speed: the cost study (cost.tsv, the engine against the tight
#                        loop in cost_vs_loop.tsv, their figures) and bench.tsv
#   make check-results   regenerate the study elsewhere and compare with results/
#   make gas-full        the freely cooling ring of 10^4 rods at e = 0.99, 0.9, 0.5 into
#                        results/gas_full/ (about 20 minutes)
#   make grid            the collapse region: struck rows p = 50 ... 10^5 at e = 0.2 ...
#                        0.95, results/collapse_grid.tsv and its answer map (minutes)
#   make ecrit-full      the full e_c(p) sweep, p = 3 ... 128, into results/ecrit_full/
#                        (about an hour on 2 cores; MPI=1 NP=... spreads it over ranks)
#   make docs            API documentation (FORD) in build/docs/index.html
#   make lint            the Fortran linter fortitude, rules in fortitude.toml
#   make test-mpi        c12-ecrit and c12-c2 on 1, 2 and 4 MPI ranks give the
#                        same bytes as the serial build (installs OpenMPI if missing)
#   make fuzz            seeded random and mutated inputs at sphere-row, its contract
#                        checked on each (FUZZ_SEED, FUZZ_COUNT, FUZZ_TIME)
#   make help            this list
#
#   make study MPI=1 NP=4   the same study, c12-ecrit and c12-c2 run on 4 MPI ranks
#
# Programs -> tables -> figures: each table is made by its study program, each
# figure by its gnuplot script from its tables; a second `make study` with
# nothing changed does nothing.

SHELL := /bin/bash
.DELETE_ON_ERROR:
.SUFFIXES:

FPM ?= fpm
RESULTS ?= results
BUILD_STAMP := build/.release-stamp
CLI_STAMP := build/.release-cli-stamp
INC_STAMP := build/.inc-stamp
BIN := build/release/bin
# the engine (root package) and the study package that uses it
SOURCES := $(wildcard include/*.h src/*.f90 src/*/*.f90 src/*/*.inc src/*/*.c study/src/*.f90 \
           study/src/*.inc study/app/*.f90) fpm.toml study/fpm.toml

# NO_XDP=1 builds without the 80-bit extended kind, as a compiler without
# real(10) does (aarch64): `make test NO_XDP=1` tests that build
KIND_FLAGS := $(if $(NO_XDP),--flag -DSPHERE_ROW_NO_XDP)
TEST_FLAGS := $(if $(NO_XDP),--profile debug $(KIND_FLAGS))

# MPI=1: c12-ecrit and c12-c2 are built with OpenMPI's mpifort (-DSPHERE_ROW_MPI)
# into their own prefix and run on NP ranks of OMP_PER_RANK threads each; every other
# program, and the build without MPI=1, needs no MPI. The launcher is
# `$(MPIRUN) $(MPIRUN_FLAGS) $(NP_FLAG) N`: on a cluster e.g.
# MPIRUN='mpirun --hostfile hosts', or MPIRUN='srun --mpi=pmix' MPIRUN_FLAGS=
# NP_FLAG=-n (srun hands its environment, OMP_NUM_THREADS too, to the ranks).
NP ?= 2
OMP_PER_RANK ?= 1
MPIRUN ?= mpirun
NP_FLAG ?= -np
MPI_BIN := build/release-mpi/bin
MPI_STAMP := build/.release-mpi-stamp
MPI_FLAGS := --flag -DSPHERE_ROW_MPI
# more ranks than cores are allowed (the test runs 4 on any machine); OpenMPI
# refuses to start as root unless told to (CI containers run as root)
MPIRUN_FLAGS ?= --oversubscribe $(if $(filter 0,$(shell id -u)),--allow-run-as-root) \
                -x OMP_NUM_THREADS=$(OMP_PER_RANK)
mpirun_np = $(MPIRUN) $(MPIRUN_FLAGS) $(NP_FLAG) $(1)
ifeq ($(MPI),1)
ECRIT_STAMP := $(MPI_STAMP)
ECRIT_RUN := $(call mpirun_np,$(NP)) $(MPI_BIN)/c12-ecrit
C2_STAMP := $(MPI_STAMP)
C2_RUN := $(call mpirun_np,$(NP)) $(MPI_BIN)/c12-c2
else
ECRIT_STAMP := $(BUILD_STAMP)
ECRIT_RUN := $(BIN)/c12-ecrit
C2_STAMP := $(BUILD_STAMP)
C2_RUN := $(BIN)/c12-c2
endif

# tables of each study program (grouped: one run writes them all)
A1 := $(RESULTS)/a1_paths.tsv $(RESULTS)/a1_answers.tsv
A2 := $(RESULTS)/a2_velocities.tsv $(RESULTS)/a2_answers.tsv
B1 := $(RESULTS)/b1_scan.tsv $(RESULTS)/b1_intervals.tsv $(RESULTS)/b1_critical.tsv \
      $(RESULTS)/b1_answers.tsv
B2 := $(RESULTS)/b2_velocities.tsv $(RESULTS)/b2_closed_forms.tsv $(RESULTS)/b2_answers.tsv
C1 := $(RESULTS)/c1_iterations.tsv $(RESULTS)/c1_starts.tsv $(RESULTS)/c1_answers.tsv
C2 := $(RESULTS)/c2_ecdf.tsv $(RESULTS)/c2_histogram.tsv $(RESULTS)/c2_convergence.tsv \
      $(RESULTS)/c2_answers.tsv
# Timings live apart: every table and figure of results/ but those under
# results/timing/ is the same on any machine; results/timing/ holds this
# machine's measurements (the study programs' wall times, the methods' CPU
# times and the platform, the survey's run times, the work-precision figure
# drawn from them), tracked as the reference machine's, so that a `make study`
# elsewhere changes nothing else (docs/testing.md: how check-docs reads them).
TIMING := $(RESULTS)/timing
METHODS := $(RESULTS)/methods_work_precision.tsv $(RESULTS)/methods_stability.tsv \
      $(RESULTS)/methods_min_distance.tsv $(TIMING)/methods_work_precision.tsv \
      $(TIMING)/methods_costs.tsv $(TIMING)/methods_platform.tsv
COLLAPSE := $(RESULTS)/collapse_survey.tsv $(RESULTS)/collapse_by_p.tsv \
      $(RESULTS)/collapse_answers.tsv $(RESULTS)/collapse_unanswered.tsv \
      $(RESULTS)/collapse_order_computed.tsv \
      $(TIMING)/collapse_survey.tsv
ECRIT := $(RESULTS)/ecrit.tsv $(RESULTS)/ecrit_answers.tsv $(RESULTS)/ecrit_map.tsv \
      $(RESULTS)/ecrit_robust.tsv
# the full e_c(p) sweep (make ecrit-full): its keys, its last row, and the rows
# that check-results regenerates with its keys and compares with its tables
ECRIT_FULL := results/ecrit_full
ECRIT_FULL_KEYS := p_min=3 n_scan=1000 p_long=21 n_scan_long=200 robust_p_max=10
ECRIT_FULL_P_MAX := 128
ECRIT_FULL_CHECK_P := 6
# machine-dependent timings (like bench.tsv): made by `make bench`, not by
# `make study`, and not compared by check-results
COST := $(RESULTS)/cost.tsv $(RESULTS)/cost_summary.tsv $(RESULTS)/cost_vs_loop.tsv
ECRIT_REPLAY := $(RESULTS)/ecrit_replay.tsv
# the freely cooling ring (c12-gas) at make study's size; the larger rings
# behind make gas-full, into results/gas_full/
GAS := $(RESULTS)/gas_haff.tsv $(RESULTS)/gas_answers.tsv $(TIMING)/gas_runs.tsv
GAS_FULL := results/gas_full
GAS_FULL_KEYS := p=10000 max_collisions=60000000
TABLES := $(A1) $(A2) $(B1) $(B2) $(C1) $(C2) $(METHODS) $(COLLAPSE) $(ECRIT) $(ECRIT_REPLAY) \
          $(GAS)
ANSWERS := $(filter %_answers.tsv,$(TABLES))

# the space-time diagrams (c12-spacetime, study/spacetime.gp): the definition's
# row, p = 30 at e = 0.6 and a long row; their tables hold a vertex wherever a
# sphere's velocity changes, megabytes for the longer runs, so they are made in
# build/spacetime and only the figures go to results/
SPACETIME := spacetime_p4_e02 spacetime_p30_e06 spacetime_p200_e05
spacetime_p4_e02_KEYS := p=4 e=0.2
spacetime_p30_e06_KEYS := p=30 e=0.6
spacetime_p200_e05_KEYS := p=200 e=0.5
SPACETIME_DIR := build/spacetime
SPACETIME_TABLES := $(foreach s,$(SPACETIME),$(foreach t,lines collisions collapses info, \
                    $(SPACETIME_DIR)/$(s)_$(t).tsv))

FIGURES := a1_paths b1_n b1_critical b2_velocities c1_secant c2_ecdf c2_histogram collapse_by_p \
           c2_convergence ecrit ecrit_map gas_haff gas_collisions
PNG := $(FIGURES:%=$(RESULTS)/%.png) $(TIMING)/methods_work_precision.png \
       $(RESULTS)/methods_stability.png $(SPACETIME:%=$(RESULTS)/%.png)
SVG := $(FIGURES:%=$(RESULTS)/%.svg) $(TIMING)/methods_work_precision.svg \
       $(RESULTS)/methods_stability.svg $(SPACETIME:%=$(RESULTS)/%.svg)

.PHONY: all help prereqs replay install uninstall check-docs test-tools test test-long test-times mutants differential readme-commands test-mpi check-layers study tables \
        figures bench callgrind check-results docs lint clean fuzz plot examples ecrit-full grid \
        gas-full

all: study

help: ## list the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed -E 's/:.*## /\t/' | expand -t 18

prereqs: ## install missing gfortran, GSL, gnuplot, fpm (Debian, root) or say how
	@bash .ci/prereqs

# the command-line program, built with the release profile (the debug build
# fpm run makes by default is about ten times slower), into $(PREFIX)/bin; a
# user-writable place by default, so no root is needed
PREFIX ?= $(HOME)/.local
install: prereqs ## the sphere-row CLI into $(PREFIX)/bin (default ~/.local; PREFIX=/path for another)
	$(FPM) install --profile release $(KIND_FLAGS) --prefix $(abspath $(PREFIX))
	@echo "install: $(abspath $(PREFIX))/bin/sphere-row"; \
	case ":$$PATH:" in *":$(abspath $(PREFIX))/bin:"*) ;; \
	*) echo "install: $(abspath $(PREFIX))/bin is not on PATH; add it, e.g. in ~/.profile:"; \
	   echo "  export PATH=\"$(abspath $(PREFIX))/bin:\$$PATH\"";; esac

uninstall: ## remove sphere-row from $(PREFIX)/bin
	rm -f $(abspath $(PREFIX))/bin/sphere-row

# README.md and docs/: every number quoted from a table of results/ against
# that table at its printed digits, every relative link, and every command
# they show run (sphere-row as installed into build/docs-prefix, on PATH),
# with the output they show; docs/cli.md's table of output lines against
# sphere-row --help (tools/check-docs)
DOCS_PREFIX := build/docs-prefix
check-docs: prereqs ## check README.md and docs/: quoted numbers, links, commands
	@mkdir -p build
	@$(MAKE) --no-print-directory install PREFIX=$(DOCS_PREFIX) > build/docs-install.log 2>&1 \
		|| { cat build/docs-install.log; exit 1; }
	PATH="$(abspath $(DOCS_PREFIX))/bin:$$PATH" python3 tools/check-docs

# the engine's and the CLI's tests (root package), then the study's (study/),
# then the tools' that build nothing (tools/test-tools --without-install:
# check-docs fails on a changed number, link or output; make test-tools adds
# make install, CI runs it); the last line adds up the three runs' `N passed,
# N failed` (a run that reports no such line, e.g. because it did not build,
# counts as one failure) (TEST_ARGS=long gives the deep versions: test-long)
# The two packages' suites run side by side (the study's printed after the
# engine's), one per core.
test: prereqs check-layers $(INC_STAMP) ## run both packages' tests; last line: N passed, N failed
	@mkdir -p build
	@bash .ci/prereqs replay
	@set -o pipefail; status=0; \
	(cd study && $(FPM) test $(TEST_FLAGS) $(if $(TEST_ARGS),-- $(TEST_ARGS))) \
		> build/test-study.log 2>&1 & study=$$!; \
	$(FPM) test $(TEST_FLAGS) $(if $(TEST_ARGS),-- $(TEST_ARGS)) 2>&1 \
		| tee build/test-engine.log || status=1; \
	wait $$study || status=1; cat build/test-study.log; \
	python3 tools/test-tools --without-install > build/test-tools.log 2>&1 || status=1; \
	cat build/test-tools.log; \
	awk '/^[0-9]+ passed, [0-9]+ failed$$/ { p += $$1; f += $$3; n++ } \
		END { f += 3 - n; printf "%d passed, %d failed\n", p, f; exit f > 0 }' \
		build/test-engine.log build/test-study.log build/test-tools.log && exit $$status

test-tools: prereqs ## the tools' own tests: check-docs fails on a changed number or link; make install
	@python3 tools/test-tools

readme-commands: prereqs ## run every command the README shows and check what it prints
	@mkdir -p build
	@$(MAKE) --no-print-directory install PREFIX=$(DOCS_PREFIX) > build/docs-install.log 2>&1 \
		|| { cat build/docs-install.log; exit 1; }
	PATH="$(abspath $(DOCS_PREFIX))/bin:$$PATH" python3 tools/check-docs --only commands README.md

differential: prereqs ## the same random rows by REV (default HEAD) and the working tree
	bash tools/differential $(or $(REV),HEAD) $(ARGS)

mutants: prereqs ## the mutation check (tools/mutants): each small bug must fail make test
	python3 tools/mutants $(if $(MECHANICAL),--mechanical $(MECHANICAL) --sample $(or $(SAMPLE),20) \
		--seed $(or $(SEED),1))

# test-long adds the near-edge rows against the replay (tools/replay-check:
# 300 rows, a few minutes on 2 cores) and a last line that counts both
test-long: prereqs $(CLI_STAMP) $(BUILD_STAMP) ## the tests in their deep versions, 300 near-edge rows against the replay, the collapse grid at a tenfold smaller vtol
	@mkdir -p build
	@set -o pipefail; status=0; \
	$(MAKE) --no-print-directory test TEST_ARGS=long | tee build/test-long.log || status=1; \
	bash .ci/prereqs replay; \
	python3 tools/replay-check sphere_row=$(BIN)/sphere-row > build/test-replay.log 2>&1 \
		|| status=1; cat build/test-replay.log; \
	if $(BIN)/c12-grid again=0.1 out=build/grid-again > build/test-grid.log 2>&1; then \
		echo "1 passed, 0 failed" >> build/test-grid.log; else status=1; \
		echo "0 passed, 1 failed" >> build/test-grid.log; fi; cat build/test-grid.log; \
	tail -q -n 1 build/test-long.log build/test-replay.log build/test-grid.log | \
		awk '/^[0-9]+ passed, [0-9]+ failed$$/ { p += $$1; f += $$3; n++ } \
		END { f += 3 - n; printf "%d passed, %d failed\n", p, f; exit f > 0 }' && exit $$status

replay: ## the high-precision replay of a scene: ARGS="p=5 e=0.2593" (tools/replay, mpmath)
	@bash .ci/prereqs replay
	@python3 tools/replay $(ARGS)

# every test's line ends in its wall time: `ok   suite/name (1.23 s)`
test-times: test ## make test, then build/test-times.tsv: each test's seconds, slowest first
	@grep -h '^\(ok  \|FAIL\) ' build/test-engine.log build/test-study.log build/test-tools.log \
		| sed -E 's/^(ok  |FAIL) +([^ ]+) \(([0-9.]+) s\).*/\3\t\2/' | sort -rn \
		| { printf 'seconds\ttest\n'; cat; } > build/test-times.tsv
	@head -n 6 build/test-times.tsv
	@awk -F '\t' 'NR > 1 { s += $$1 } END { printf "%d tests, %.1f s in all\n", NR - 1, s }' \
		build/test-times.tsv

study: prereqs ## every task's tables and figures, answers.tsv and summary.md in results/
	@$(MAKE) --no-print-directory $(RESULTS)/summary.md $(PNG) $(SVG) $(ECRIT_REPLAY)

tables: $(TABLES) ## the study's tables only

figures: $(PNG) $(SVG) ## the study's figures only

bench: prereqs ## speed: cost per collision against p and against the tight loop (cost*.tsv, figures) and bench.tsv
	@$(MAKE) --no-print-directory $(RESULTS)/bench.tsv $(RESULTS)/cost.png $(RESULTS)/cost.svg \
		$(RESULTS)/cost_loop.png $(RESULTS)/cost_loop.svg

# exact counts, not times: valgrind is installed on demand, so `make test` and
# `make study` never need it; bench.tsv copies the last measured counts
callgrind: $(BUILD_STAMP) ## quad operations per collision of c2's lean path (valgrind)
	bash tools/callgrind-quad-ops $(BIN) $(RESULTS)

# The layers: the core below the umbrella module (src/core: kinds, status,
# format, the policy; src/engine: the per-kind engine; src/collapse: its
# rules) never imports it; everything above it (src/cli, the CLI, study,
# tests) never imports a per-kind engine module but the umbrella's names; the
# root package links no GSL.
CORE := $(wildcard src/core/*.f90 src/engine/*.f90 src/engine/*.inc src/collapse/*.f90 \
        src/collapse/*.inc)
ABOVE := $(wildcard src/cli/*.f90 app/*.f90 test/*.f90 study/*/*.f90 study/*/*.inc)
check-layers: ## check the layer rules (umbrella imports, per-kind imports, GSL)
	@! grep -nE '^ *use +sphere_row *(,|$$)' $(CORE) || { echo "the core imports the umbrella"; exit 1; }
	@! grep -nE '^ *use +sphere_row_engine_' $(ABOVE) || { echo "a per-kind engine module used above the umbrella"; exit 1; }
	@! grep -niE '^ *link *=.*gsl' fpm.toml || { echo "the root package links GSL"; exit 1; }

# fpm does not see edits of an included template (src/*/*.inc, study/src/*.inc):
# drop the objects of every source that includes one, in both packages' build
# trees of either compiler (gfortran, or mpifort for MPI=1; fpm names an
# object after its path, src/engine/x.f90 -> src_engine_x.f90.o, and in the
# study's tree the root's sources with a leading .._ and its own without
# study/: study/src/x.f90 -> src_x.f90.o), and the linked
# programs, which fpm does not relink on its own, so that fpm builds them again;
# and the objects of the programs and tests, which a build of the library alone
# (fpm build) would leave compiled against the old modules.
$(INC_STAMP): $(wildcard src/*/*.inc study/src/*.inc)
	@mkdir -p build
	for f in $$(grep -rl --include='*.f90' '^ *include "' src study/src); do \
		rm -f {,study/}build/{gfortran,mpifort}_*/*/{,.._}$$(echo $$f | tr / _).o* \
			study/build/{gfortran,mpifort}_*/*/$$(echo $${f#study/} | tr / _).o*; done
	rm -f {,study/}build/{gfortran,mpifort}_*/{app,test}/*
	rm -f {,study/}build/{gfortran,mpifort}_*/*/{app,test,example}_*.o*
	@touch $@

# the study package's programs (with tsv-compare); the CLI is not needed here
$(BUILD_STAMP): $(SOURCES) $(INC_STAMP)
	cd study && $(FPM) install --profile release $(KIND_FLAGS) --prefix $(abspath build/release)
	@touch $@

# the sphere-row CLI beside them, for the bench's whole-process timings
$(CLI_STAMP): $(SOURCES) $(INC_STAMP) $(wildcard app/*.f90)
	$(FPM) install --profile release $(KIND_FLAGS) --prefix $(abspath build/release)
	@touch $@

# the same with OpenMPI's compiler wrapper and the MPI code of the ranks
# module, in its own prefix (fpm's build tree of another compiler is its own)
$(MPI_STAMP): $(SOURCES) $(INC_STAMP)
	@bash .ci/prereqs mpi
	cd study && FPM_FC=mpifort $(FPM) install --profile release $(KIND_FLAGS) $(MPI_FLAGS) \
		--prefix $(abspath build/release-mpi)
	@touch $@

# run one study program, keeping its wall time apart from the tables; a third
# argument is the command that runs it (default: the serial build's program)
define study_run
	@mkdir -p $(TIMING)
	@start=$$(date +%s.%N); $(or $(3),$(BIN)/$(1)) out=$(RESULTS) $(2); \
	end=$$(date +%s.%N); \
	awk -v s=$$start -v e=$$end -v p=$(1) 'BEGIN { printf "%s\t%.3f\n", p, e - s }' \
		> $(TIMING)/$(1).tsv
endef

$(A1) &: $(BUILD_STAMP)
	$(call study_run,c12-a1)
$(A2) &: $(BUILD_STAMP)
	$(call study_run,c12-a2)
$(B1) &: $(BUILD_STAMP)
	$(call study_run,c12-b1)
$(B2) &: $(BUILD_STAMP)
	$(call study_run,c12-b2)
$(C1) &: $(BUILD_STAMP)
	$(call study_run,c12-c1)
# c2: the main sample of 10^6 runs, its convergence table up to 10^7
$(C2) &: $(C2_STAMP)
	$(call study_run,c12-c2,nmax=10000000,$(C2_RUN))
$(COLLAPSE) &: $(BUILD_STAMP)
	$(call study_run,c12-collapse,cap=100000 n_before=100)
$(METHODS) &: $(BUILD_STAMP)
	$(call study_run,c12-methods)
$(ECRIT) &: $(ECRIT_STAMP)
	$(call study_run,c12-ecrit,,$(ECRIT_RUN))
# the e_c table's points of rows p <= 6 run again by the independent replay
$(ECRIT_REPLAY): $(ECRIT) $(CLI_STAMP) tools/replay tools/replay-ecrit
	@bash .ci/prereqs replay
	python3 tools/replay-ecrit $(RESULTS) p_max=6 sphere_row=$(abspath $(BIN))/sphere-row
$(COST) &: $(BUILD_STAMP)
	$(call study_run,c12-cost)
$(GAS) &: $(BUILD_STAMP)
	$(call study_run,c12-gas)

$(RESULTS)/answers.tsv $(RESULTS)/summary.md &: $(ANSWERS) $(BUILD_STAMP)
	$(BIN)/c12-summary out=$(RESULTS)

# BENCH_PARTS=loop,whole measures only those parts of bench.tsv anew and keeps
# the other rows as they were (c12-bench parts=...)
$(RESULTS)/bench.tsv: $(BUILD_STAMP) $(CLI_STAMP) $(TABLES) $(COST)
	$(BIN)/c12-bench out=$(RESULTS) $(if $(BENCH_PARTS),parts=$(BENCH_PARTS))

# figures: the script is a prerequisite of its figure
$(RESULTS)/%.png: study/%.gp
	gnuplot -e "dir='$(RESULTS)'; term='png'; out='$@'" $<
$(RESULTS)/%.svg: study/%.gp
	gnuplot -e "dir='$(RESULTS)'; term='svg'; out='$@'" $<

$(RESULTS)/a1_paths.png $(RESULTS)/a1_paths.svg: $(A1)
$(RESULTS)/b1_n.png $(RESULTS)/b1_n.svg: $(B1)
$(RESULTS)/b1_critical.png $(RESULTS)/b1_critical.svg: $(B1)
$(RESULTS)/b2_velocities.png $(RESULTS)/b2_velocities.svg: $(B2) $(B1)
$(RESULTS)/c1_secant.png $(RESULTS)/c1_secant.svg: $(C1)
$(RESULTS)/c2_ecdf.png $(RESULTS)/c2_ecdf.svg: $(C2)
$(RESULTS)/collapse_by_p.png $(RESULTS)/collapse_by_p.svg: $(COLLAPSE)
$(RESULTS)/c2_histogram.png $(RESULTS)/c2_histogram.svg: $(C2)
$(RESULTS)/c2_convergence.png $(RESULTS)/c2_convergence.svg: $(C2)
$(RESULTS)/ecrit.png $(RESULTS)/ecrit.svg: $(ECRIT)
$(RESULTS)/ecrit_map.png $(RESULTS)/ecrit_map.svg: $(ECRIT)
$(RESULTS)/cost.png $(RESULTS)/cost.svg: $(COST)
$(RESULTS)/cost_loop.png $(RESULTS)/cost_loop.svg: $(COST)
$(RESULTS)/gas_haff.png $(RESULTS)/gas_haff.svg: $(GAS)
$(RESULTS)/gas_collisions.png $(RESULTS)/gas_collisions.svg: $(GAS)

# the space-time diagrams: one run of c12-spacetime writes a scene's four
# tables, the script draws both formats in one run
.SECONDARY: $(SPACETIME_TABLES)
$(SPACETIME_DIR)/%_lines.tsv $(SPACETIME_DIR)/%_collisions.tsv $(SPACETIME_DIR)/%_collapses.tsv \
		$(SPACETIME_DIR)/%_info.tsv: $(BUILD_STAMP)
	$(BIN)/c12-spacetime out=$(SPACETIME_DIR) name=$* $($*_KEYS)
$(RESULTS)/spacetime_%.png $(RESULTS)/spacetime_%.svg: study/spacetime.gp \
		$(foreach t,lines collisions collapses info,$(SPACETIME_DIR)/spacetime_%_$(t).tsv)
	gnuplot -e "dir='$(SPACETIME_DIR)'; name='spacetime_$*'; out='$(RESULTS)/spacetime_$*'" $<

# the space-time diagram of any scene the scene keys describe, into
# $(PLOT).png and $(PLOT).svg; its tables in build/plot
PLOT ?= plot
plot: prereqs ## space-time diagram of a scene: ARGS="p=30 e=0.6" -> plot.png, plot.svg (PLOT=name)
	@$(MAKE) --no-print-directory $(BUILD_STAMP)
	$(BIN)/c12-spacetime out=build/plot name=plot $(ARGS)
	gnuplot -e "dir='build/plot'; name='plot'; out='$(PLOT)'" study/spacetime.gp
	@echo "plot: wrote $(PLOT).png and $(PLOT).svg"

# the example programs (example/, [[example]] in fpm.toml) as a user of the
# package runs them. `fpm run --example` without a name runs every example in
# fpm 0.12, in the order of fpm.toml, goes on past one that fails and exits
# with that one's status; here each runs on its own under its name, so that a
# failure says which.
examples: prereqs ## build and run every example program (example/); fails if one fails
	@mkdir -p build
	@$(FPM) run $(TEST_FLAGS) --example --runner echo > build/examples.list \
		2> build/examples-build.log || { cat build/examples.list build/examples-build.log; exit 1; }
	@set -o pipefail; ran=0; failed=0; \
	for bin in $$(grep '/example/' build/examples.list); do \
		echo "== $$(basename $$bin)"; ran=$$((ran + 1)); \
		$$bin || { echo "$$(basename $$bin): failed"; failed=$$((failed + 1)); }; done; \
	echo "examples: $$ran ran, $$failed failed"; [ $$ran -gt 0 ] && [ $$failed -eq 0 ]

# the methods' scripts write both formats in one run
$(TIMING)/methods_work_precision.png $(TIMING)/methods_work_precision.svg &: \
		study/work_precision.gp $(METHODS)
	gnuplot -e "dir='$(RESULTS)'; out='$(TIMING)/methods_work_precision'" $<
$(RESULTS)/methods_stability.png $(RESULTS)/methods_stability.svg &: \
		study/stability_map.gp $(METHODS)
	gnuplot -e "dir='$(RESULTS)'; out='$(RESULTS)/methods_stability'" $<

check-results: prereqs ## regenerate the tables in build/ and compare with results/
	rm -rf build/check
	$(MAKE) --no-print-directory RESULTS=build/check tables build/check/answers.tsv
	$(BIN)/tsv-compare committed=$(RESULTS) fresh=build/check
	$(BIN)/c12-ecrit $(ECRIT_FULL_KEYS) p_max=$(ECRIT_FULL_CHECK_P) out=build/check/ecrit_full
	bash tools/check-ecrit-rows $(ECRIT_FULL) build/check/ecrit_full $(ECRIT_FULL_CHECK_P)

# the collapse region: the definition's scene with more spheres over a grid
# of p and e (a few minutes: its longest rows spend their budget), its table,
# the runs' wall times in timing/, and the answer map
GRID := $(RESULTS)/collapse_grid.tsv $(RESULTS)/timing/collapse_grid.tsv
grid: prereqs $(BUILD_STAMP) ## the collapse region: p = 50 ... 10^5 by e = 0.2 ... 0.95, collapse_grid.tsv and its map
	$(call study_run,c12-grid)
	set -e; for t in png svg; do \
		gnuplot -e "dir='$(RESULTS)'; term='$$t'; out='$(RESULTS)/collapse_grid.$$t'" study/collapse_grid.gp; done

# the cooling ring of 10^4 rods (GAS_FULL_KEYS), its tables and figures in
# results/gas_full/ (about 20 minutes: the ring at e = 0.9 spends most of its
# budget in its collapses)
gas-full: prereqs $(BUILD_STAMP) ## the cooling ring of 10^4 rods into results/gas_full/
	@mkdir -p $(GAS_FULL)
	$(BIN)/c12-gas $(GAS_FULL_KEYS) out=$(GAS_FULL)
	set -e; for f in gas_haff gas_collisions; do for t in png svg; do \
		gnuplot -e "dir='$(GAS_FULL)'; term='$$t'; out='$(GAS_FULL)/$$f.$$t'" study/$$f.gp; done; done

# the full e_c(p) sweep: its tables, its two figures, and sweep.tsv with its
# wall time, ranks and threads (MPI=1 NP=... for ranks; OMP_NUM_THREADS threads)
ecrit-full: prereqs $(ECRIT_STAMP) $(CLI_STAMP) ## the full e_c(p) sweep p = 3 ... 128 into results/ecrit_full/, its points run again by the replay
	@mkdir -p $(ECRIT_FULL)
	@set -e; start=$$(date +%s.%N); \
	$(ECRIT_RUN) $(ECRIT_FULL_KEYS) p_max=$(ECRIT_FULL_P_MAX) out=$(ECRIT_FULL); \
	end=$$(date +%s.%N); \
	awk -v s=$$start -v e=$$end -v r=$(if $(filter 1,$(MPI)),$(NP),1) \
		-v t=$(if $(filter 1,$(MPI)),$(OMP_PER_RANK),$${OMP_NUM_THREADS:-$$(nproc)}) \
		-v c=$$(nproc) -v k="$(ECRIT_FULL_KEYS) p_max=$(ECRIT_FULL_P_MAX)" \
		'BEGIN { printf "keys\tseconds\tranks\tthreads_per_rank\tcores\n%s\t%.0f\t%d\t%s\t%d\n", k, e - s, r, t, c }' \
		> $(ECRIT_FULL)/sweep.tsv
	set -e; for f in ecrit ecrit_map; do for t in png svg; do \
		gnuplot -e "dir='$(ECRIT_FULL)'; term='$$t'; out='$(ECRIT_FULL)/$$f.$$t'" study/$$f.gp; done; done
	@bash .ci/prereqs replay
	python3 tools/replay-ecrit $(ECRIT_FULL) p_max=20 sphere_row=$(abspath $(BIN))/sphere-row

# c12-ecrit on a short range of p (rows 3 ... 6 take the real(16) and
# rate-map stages, so every field of a row travels between ranks): the serial
# build on 1 and 2 threads and the MPI build on 1, 2 and 4 ranks (4 ranks also
# for 2 rows, where ranks have none) must write the same bytes; so must
# c12-c2 on a short stream of 5 blocks whose third straddles n (4 ranks: one
# with two blocks, one with the straddling block's main and rest counts).
# In the recipe, `ranks PREFIX PROGRAM KEYS TABLES` is that comparison for one
# program: its runs on 1 and 2 threads and on 1, 2 and 4 ranks, each in
# build/test-mpi/PREFIX..., must write the serial run's TABLES.
ECRIT_QUICK := p_min=3 p_max=10 n_scan=30
C2_QUICK := n=25000 nmax=45000
ECRIT_TABLES := ecrit.tsv ecrit_answers.tsv ecrit_map.tsv ecrit_robust.tsv
C2_TABLES := c2_ecdf.tsv c2_histogram.tsv c2_convergence.tsv c2_answers.tsv
test-mpi: prereqs $(BUILD_STAMP) $(MPI_STAMP) ## c12-ecrit and c12-c2 on 1, 2, 4 MPI ranks == serial, byte for byte
	@rm -rf build/test-mpi
	@set -e; t=build/test-mpi; failed=0; \
	run() { dir=$$1; shift; echo "$$dir: $$*"; \
		if ! "$$@" out=$$t/$$dir > $$t/$$dir.log 2>&1; then \
			cat $$t/$$dir.log; echo "$$dir: failed"; failed=$$((failed + 1)); fi; }; \
	same() { a=$$1; b=$$2; shift 2; for f in "$$@"; do \
		cmp $$t/$$a/$$f $$t/$$b/$$f || failed=$$((failed + 1)); done; }; \
	ranks() { pre=$$1; program=$$2; keys=$$3; tables=$$4; \
		run $${pre}serial env OMP_NUM_THREADS=1 $(BIN)/$$program $$keys; \
		run $${pre}threads2 env OMP_NUM_THREADS=2 $(BIN)/$$program $$keys; \
		same $${pre}serial $${pre}threads2 $$tables; \
		for np in 1 2 4; do \
			run $${pre}np$$np $(call mpirun_np,$$np) $(MPI_BIN)/$$program $$keys; \
			same $${pre}serial $${pre}np$$np $$tables; done; }; \
	mkdir -p $$t; \
	ranks "" c12-ecrit "$(ECRIT_QUICK)" "$(ECRIT_TABLES)"; \
	run serial_two env OMP_NUM_THREADS=1 $(BIN)/c12-ecrit p_min=3 p_max=4; \
	run np4_two $(call mpirun_np,4) $(MPI_BIN)/c12-ecrit p_min=3 p_max=4; \
	same serial_two np4_two $(ECRIT_TABLES); \
	ranks c2_ c12-c2 "$(C2_QUICK)" "$(C2_TABLES)"; \
	lines=$$($(call mpirun_np,2) $(MPI_BIN)/c12-c2 nmax=0 2>&1 >/dev/null | grep -c '^c12-c2: ' || true); \
	if [ "$$lines" != 1 ]; then echo "refused key on 2 ranks: told $$lines times"; failed=$$((failed + 1)); fi; \
	if [ $$failed -gt 0 ]; then echo "test-mpi: $$failed runs or comparisons failed"; exit 1; fi; \
	echo "test-mpi: c12-ecrit and c12-c2 on 1, 2 and 4 ranks and 1 and 2 threads wrote the same tables;" \
		"a refused key is told once"

# The fuzz: FUZZ_COUNT inputs made from FUZZ_SEED (key=value pairs at the edges of
# every range, mutated command lines, scene files with junk, paths that are not
# files) run against the sphere-row that `make test` tests (its run-time checks
# turn an overrun into a crash the fuzz sees); it fails on a signal, a hang, a
# malformed answer, a refusal that is not one line with exit 2, or a pass longer
# than FUZZ_TIME seconds.
FUZZ_SEED ?= 1
FUZZ_COUNT ?= 10000
FUZZ_TIME ?= 60
fuzz: ## throw FUZZ_COUNT seeded hostile inputs at sphere-row and check its contract
	@mkdir -p build
	@$(FPM) build $(TEST_FLAGS) > build/fuzz-build.log 2>&1 || { cat build/fuzz-build.log; exit 1; }
	@bin=$$($(FPM) run $(TEST_FLAGS) --runner echo sphere-row 2>/dev/null | tail -1); \
	python3 tools/fuzz.py --binary "$$bin" --seed $(FUZZ_SEED) --count $(FUZZ_COUNT) \
		--time-limit $(FUZZ_TIME)

docs: ## API documentation from the !> comments (FORD) in build/docs/index.html
	@bash .ci/prereqs docs
	ford ford.md

lint: ## check the Fortran sources with fortitude (rules and exceptions: fortitude.toml)
	@bash .ci/prereqs lint
	fortitude check src app test study/src study/app study/test tools/testsuite/src

clean: ## remove the build directories (results/ stays: it is committed)
	rm -rf build study/build tools/testsuite/build
