# footnav top-level Makefile.
#
#   make            static library + harness (bin/harness)
#   make test       every CMocka suite (float and double builds), the CLI
#                   tests, the golden-vector cross-checks, the no-allocation check
#   make sanitize   the suites and CLI tests under ASan + UBSan
#   make firmware   the reference firmware image for Cortex-M4F: size and stack report
#   make firmware-bench  the firmware in qemu-system-arm: instructions per call
#   make bench      benchmarks (figures quoted in docs/ come from here)
#   make coverage   line and branch coverage of src/ by the suites (build/cov; not part of make test)
#   make coverage-harness  the same of harness/ by the CLI tests (build/hcov; not part of make test)
#   make simgap-validation  the gap diagnosis on withheld effects -> docs/simgap-validation.md
#   make deps       install the Debian packages (scripts/bootstrap.sh)
#   make install    the library, its headers, footnav.pc and the harness (as
#                   footnav-harness) under PREFIX (/usr/local); DESTDIR stages
#   make uninstall  removes what make install put
#   make clean
#
# The core calls the port's fnav_port_assert_failed(), which lives in libhx.a
# (port/linux): libhx.a is named again after libfootnav.a on link lines.
#
# Sources are discovered: src/*.c is the core, harness/*.c + port/linux/*.c the
# Linux tool, tests/test_*.c the CMocka suites, tests/bench_*.c the benchmarks,
# tests/cli/test_*.sh the command-line tests.

CC      ?= gcc
AR      ?= ar
PYTHON  ?= /usr/bin/python3
BUILD   ?= build/host
HARNESS ?= bin/harness
OPT     ?= -O2 -g
SAN     ?=
FNAV_DEFS ?=

WARN     := -std=c99 -pedantic -Wall -Wextra -Wmissing-prototypes -Wdouble-promotion \
            -Wshadow -Wstrict-prototypes -Werror
CPPFLAGS := -Iinclude -Iport/linux -Iharness -Itests/support -Iport/cortex-m $(FNAV_DEFS)
CFLAGS_CORE := $(WARN) $(OPT) $(SAN)
# The harness, the Linux port and the tests may use POSIX.
CFLAGS_HOST := $(WARN) $(OPT) $(SAN) -D_POSIX_C_SOURCE=200809L
LDLIBS_HOST := -lcjson -lgsl -lgslcblas -lserialport -lz -lm
LDLIBS_TEST := -lcmocka $(LDLIBS_HOST)

CORE_SRC    := $(wildcard src/*.c)
HX_SRC      := $(filter-out harness/main.c,$(wildcard harness/*.c)) $(wildcard port/linux/*.c)
TEST_SRC    := $(wildcard tests/test_*.c)
BENCH_SRC   := $(wildcard tests/bench_*.c)
ENDURE_SRC  := $(wildcard tests/endure_*.c)
TESTHELP_SRC:= $(wildcard tests/support/*.c) port/cortex-m/fnav_cm_ring.c port/cortex-m/fnav_port_cortexm.c \
               port/cortex-m/fnav_cm_est.c port/cortex-m/fnav_cm_app.c

CORE_OBJ    := $(CORE_SRC:%.c=$(BUILD)/obj/%.o)
HX_OBJ      := $(HX_SRC:%.c=$(BUILD)/obj/%.o)
TESTHELP_OBJ:= $(TESTHELP_SRC:%.c=$(BUILD)/obj/%.o)
LIB         := $(BUILD)/libfootnav.a
HXLIB       := $(BUILD)/libhx.a
TEST_BINS   := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCH_BINS  := $(BENCH_SRC:tests/%.c=$(BUILD)/tests/%)
ENDURE_BINS := $(ENDURE_SRC:tests/%.c=$(BUILD)/tests/%)

# Symbols no core object may reference: allocation, stdio, process control.
FORBIDDEN := malloc|calloc|realloc|free|_sbrk|sbrk|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|vsnprintf|puts|fputs|putchar|fputc|putc|fopen|fclose|fread|fwrite|fflush|stdout|stderr|stdin|_impure_ptr|__printf_chk|__fprintf_chk|__sprintf_chk|__snprintf_chk|exit|abort|system

.PHONY: all test check-suites test-double test-cli vectors-check nm-check sanitize \
        firmware firmware-bench bench deps clean run fuzz valgrind lint longrun install uninstall coverage \
        coverage-harness

all: $(LIB) $(HARNESS) nm-check

# The FNAV_* options size the objects (fnav_config.h): every object of
# $(BUILD) is rebuilt when FNAV_DEFS changes, so the library make install
# copies was built with the FNAV_DEFS its footnav.pc gives a program.
DEFS_STAMP := $(BUILD)/fnav-defs.stamp
# (make's own file function: FNAV_DEFS may hold quotes, -DFNAV_CONFIG_FILE='"my.h"')
# Goals that compile nothing in $(BUILD) leave the stamp alone (a make
# uninstall or lint without the FNAV_DEFS of the build made it rebuild all).
ifneq ($(filter-out clean deps uninstall lint,$(or $(MAKECMDGOALS),all)),)
ifneq ($(file <$(DEFS_STAMP)),$(strip $(FNAV_DEFS)))
$(shell mkdir -p $(BUILD))
$(file >$(DEFS_STAMP),$(strip $(FNAV_DEFS)))
endif
endif

# Made when missing (a fresh tree, or make clean earlier in the same run):
# it records FNAV_DEFS too, or a later make with other FNAV_DEFS would find
# the objects up to date. One line: make expands a recipe before running it.
$(DEFS_STAMP):
	$(shell mkdir -p $(dir $@))$(file >$@,$(strip $(FNAV_DEFS)))

$(BUILD)/obj/src/%.o: src/%.c $(DEFS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_CORE) -MMD -MP -c $< -o $@

$(BUILD)/obj/%.o: %.c $(DEFS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_HOST) -MMD -MP -c $< -o $@

$(LIB): $(CORE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(AR) rcs $@ $^

$(HXLIB): $(HX_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(AR) rcs $@ $^

# The core calls the port's fnav_port_assert_failed (in libhx via
# port/linux), so libhx is named again after the core library.
$(HARNESS): $(BUILD)/obj/harness/main.o $(HXLIB) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(SAN) -o $@ $^ $(HXLIB) $(LDLIBS_HOST)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TESTHELP_OBJ) $(HXLIB) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(SAN) -o $@ $^ $(HXLIB) $(LDLIBS_TEST)

# tests/test_build: a program of files compiled apart, tests/build_other.c
# five times over besides the suite (build_other.h): with the library's
# options (same), with fnav_real_t flipped, float <-> double (real), with
# the firmware's options (fw), and with the library's options under a
# layout-changing flag, -fpack-struct (pack) and -fshort-enums (senum);
# each then calls every _init, which says FNAV_E_BUILD unless the file's
# FNAV_BUILD_TAG and its sizes of the object and configuration are the
# library's.
BUILD_OTHER_OBJ := $(BUILD)/obj/tests/build_other_same.o $(BUILD)/obj/tests/build_other_real.o \
                   $(BUILD)/obj/tests/build_other_fw.o $(BUILD)/obj/tests/build_other_pack.o \
                   $(BUILD)/obj/tests/build_other_senum.o
BUILD_OTHER_DEFS_same :=
BUILD_OTHER_DEFS_real := -DBUILD_OTHER_FLIP_REAL=1
BUILD_OTHER_DEFS_fw := -DFNAV_CONFIG_FILE='"fnav_cm_fw_config.h"'
BUILD_OTHER_DEFS_pack := -fpack-struct
BUILD_OTHER_DEFS_senum := -fshort-enums

$(BUILD)/obj/tests/build_other_%.o: tests/build_other.c $(DEFS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(BUILD_OTHER_DEFS_$*) -DBUILD_OTHER_NAME=$* $(CFLAGS_HOST) -MMD -MP -c $< -o $@

$(BUILD)/tests/test_build: $(BUILD)/obj/tests/test_build.o $(BUILD_OTHER_OBJ) $(TESTHELP_OBJ) $(HXLIB) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(SAN) -o $@ $^ $(HXLIB) $(LDLIBS_TEST)

# The core must not allocate, print or exit (checked on every build).
nm-check: $(LIB)
	@if nm -u $(LIB) | grep -E -w '$(FORBIDDEN)'; then \
	  echo "nm-check: the core library references the symbols above (no allocation or libc I/O allowed in src/)"; exit 1; \
	else echo "nm-check: core library is allocation-free and I/O-free"; fi

# The measurements tests/endure_*.c are built with the suites (so they
# cannot rot unseen, also in the double and sanitizer builds), not run.
check-suites: $(TEST_BINS) $(ENDURE_BINS)
	@set -e; for t in $(TEST_BINS); do echo "== $$t"; $$t; done

# The CLI tests, one after the other (scripts/run_cli_tests.sh). With
# FNAV_REQUIRE_DATA=1 (CI) a CLI test that skips checks for want of the
# shared data fails instead; with FNAV_REQUIRE_TOOLS=1 (CI) one that skips
# checks for want of a tool (socat, the ARM toolchain, numpy/scipy) does.
test-cli: $(HARNESS)
	@HARNESS=$(abspath $(HARNESS)) sh scripts/run_cli_tests.sh $(BUILD) tests/cli/test_*.sh

test-double:
	$(MAKE) BUILD=build/double HARNESS=build/double/harness FNAV_DEFS=-DFNAV_USE_DOUBLE=1 check-suites

vectors-check:
	@sh scripts/check_vectors.sh

test: all check-suites test-double test-cli vectors-check
	@echo "make test: all passed"

sanitize:
	$(MAKE) BUILD=build/san HARNESS=build/san/harness OPT="-O1 -g" \
	  SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
	  check-suites test-cli
	@echo "make sanitize: all passed under ASan + UBSan"

# make coverage: the suites built in $(COV_BUILD) with --coverage at -O0
# (SAN is the flag variable every compile and link line carries) and run;
# then scripts/coverage.sh prints line and branch coverage of src/*.c (and
# of the inline functions of include/footnav/) per file and in total, and
# leaves the annotated sources in $(COV_BUILD)/gcov/. The CLI tests are not
# counted. Old counts are removed first. Not part of make test or CI.
COV_BUILD := build/cov
coverage:
	@find $(COV_BUILD) -name '*.gcda' -delete 2>/dev/null || true
	$(MAKE) BUILD=$(COV_BUILD) HARNESS=$(COV_BUILD)/harness OPT="-O0 -g" SAN=--coverage check-suites
	@sh scripts/coverage.sh $(COV_BUILD)

# make coverage-harness: the same for harness/*.c, run by the suites (some
# test the harness's readers and writers) and the CLI tests
# (tests/cli/test_*.sh, as make test-cli runs them) against a --coverage -O0
# build in $(HCOV_BUILD); about 15 minutes. Not part of make test or CI.
HCOV_BUILD := build/hcov
coverage-harness:
	@find $(HCOV_BUILD) -name '*.gcda' -delete 2>/dev/null || true
	$(MAKE) BUILD=$(HCOV_BUILD) HARNESS=$(HCOV_BUILD)/harness OPT="-O0 -g" SAN=--coverage check-suites test-cli
	@sh scripts/coverage.sh $(HCOV_BUILD) harness

# ---------------------------------------------------------------- firmware
# make firmware: the reference firmware image for a generic Cortex-M4F
# (port/cortex-m, docs/firmware.md): links, fails on any allocation or libc
# I/O, prints flash/RAM against the budget and the worst-case stack per entry
# point from -fstack-usage / -fcallgraph-info=su.
# make firmware-bench: the same code as a semihosting image for
# qemu-system-arm (mps2-an386, -icount shift=0) replaying a piece of a real
# walk; instructions per call, checked against the same code built for the host.
ARM_CC    ?= arm-none-eabi-gcc
ARM_AR    ?= arm-none-eabi-ar
ARM_NM    ?= arm-none-eabi-nm
ARM_SIZE  ?= arm-none-eabi-size
ARM_OBJDUMP ?= arm-none-eabi-objdump
QEMU      ?= qemu-system-arm
ARM_BUILD := build/arm
ARM_ARCH  := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
ARM_CFLAGS := $(ARM_ARCH) -Os -g -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su $(WARN)
FW_DEFS   ?=
# The library options of the firmware (core and port must agree on sizes).
FW_CONFIG := -DFNAV_CONFIG_FILE='"fnav_cm_fw_config.h"'
ARM_CPPFLAGS := -Iinclude -Iport/cortex-m $(FW_CONFIG) $(FW_DEFS)
ARM_LDFLAGS := $(ARM_ARCH) -nostartfiles --specs=nano.specs -Wl,--gc-sections -Lport/cortex-m/ld
ARM_LDLIBS := -lm -lc -lgcc
ARM_CORE_OBJ := $(CORE_SRC:%.c=$(ARM_BUILD)/obj/%.o)
ARM_LIB   := $(ARM_BUILD)/libfootnav.a
# Budget (issue 7): whole image with every estimator.
FW_FLASH_BUDGET ?= 49152
FW_RAM_BUDGET   ?= 24576
# Stack reserved at the bottom of RAM, below .data and .bss: it must hold the
# stack report's worst case, which nests the interrupt levels of
# FW_STACK_PRIORITIES (HANDLER=LEVEL; unnamed handlers at level 0) and counts
# the board's fnav_cm_imu_read as at least FW_IMU_READ_ROOM bytes (the image
# holds a stub of 0). The default: a board whose SysTick preempts the
# sample-ready interrupt (a priority many vendor HALs give it) and reads its
# IMU in 56 bytes (an SPI burst into a local buffer, scaled: the firmware
# audit's board): thread 1,296 + 104 + 112 + 104 + SysTick 20 = 1,636,
# rounded up to 8 (AAPCS). It fills the RAM budget: docs/firmware.md, "The
# stack reserve". FW_BOARD_SRC: a board's own files, linked into the image
# and measured by the report (`make firmware FW_BOARD_SRC=board.c`).
FW_STACK_SIZE   ?= 1640
FW_STACK_PRIORITIES ?= SysTick_Handler=1
FW_IMU_READ_ROOM ?= 56
FW_BOARD_SRC    ?=

FW_COMMON := port/cortex-m/fnav_cm_ring.c port/cortex-m/fnav_port_cortexm.c port/cortex-m/fnav_cm_est.c \
             port/cortex-m/fnav_cm_app.c port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_fault.c
FW_OBJ    := $(patsubst %.c,$(ARM_BUILD)/obj/%.o,$(FW_COMMON) port/cortex-m/fnav_cm_main.c $(FW_BOARD_SRC))
FW_ELF    := $(ARM_BUILD)/footnav-fw.elf
# The benchmark image: profiling marks on, semihosting, a generated slice.
FW_SLICE_LOG   ?= vectors/walk.bin
FW_SLICE_FIRST ?= 0
FW_SLICE_COUNT ?= 16539
FW_SLICE_C := $(ARM_BUILD)/gen/fnav_cm_slice_data.c
FW_SLICE_BIN := $(ARM_BUILD)/gen/slice.bin
FWBENCH_SRC := $(FW_COMMON) port/cortex-m/fnav_cm_bench.c port/cortex-m/fnav_cm_semihost.c
FWBENCH_OBJ := $(patsubst %.c,$(ARM_BUILD)/bench/%.o,$(FWBENCH_SRC)) $(ARM_BUILD)/bench/gen/fnav_cm_slice_data.o
BENCH_ELF := $(ARM_BUILD)/footnav-bench.elf
FW_ICOUNT_SHIFT ?= 0
# Semihosting console on stdout (without a chardev QEMU 7.2 writes it to
# stderr); no display, no serial, no monitor.
QEMU_FLAGS := -M mps2-an386 -display none -monitor none -serial none -chardev stdio,id=fwsh \
              -semihosting-config enable=on,target=native,chardev=fwsh -icount shift=$(FW_ICOUNT_SHIFT)
FW_HOSTREF := $(BUILD)/fw/footnav-bench-host
FW_SLICE_GEN := $(BUILD)/fw/fw_slice

# Rebuild the images when the firmware options change (FW_DEFS, the slice,
# the compiler's flags: `make firmware ARM_CFLAGS=...` objects were reused by
# a later plain build).
FW_STAMP  := $(ARM_BUILD)/fw-options.stamp
FW_OPTIONS := $(FW_DEFS) | $(FW_SLICE_LOG) $(FW_SLICE_FIRST) $(FW_SLICE_COUNT) | $(FW_STACK_SIZE) | $(FW_BOARD_SRC) | $(ARM_CC) $(ARM_CFLAGS)
ifneq ($(filter firmware firmware-bench $(ARM_BUILD)/%,$(MAKECMDGOALS)),)
$(shell mkdir -p $(ARM_BUILD) && (echo '$(FW_OPTIONS)' | cmp -s - $(FW_STAMP) || echo '$(FW_OPTIONS)' > $(FW_STAMP)))
endif

$(FW_STAMP):
	@mkdir -p $(dir $@)
	@echo '$(FW_OPTIONS)' > $@

$(ARM_BUILD)/obj/%.o: %.c $(FW_STAMP)
	@mkdir -p $(dir $@)
	$(ARM_CC) $(ARM_CPPFLAGS) $(ARM_CFLAGS) -MMD -MP -c $< -o $@

$(ARM_BUILD)/bench/%.o: %.c $(FW_STAMP)
	@mkdir -p $(dir $@)
	$(ARM_CC) $(ARM_CPPFLAGS) -DFNAV_CM_PROFILE=1 $(ARM_CFLAGS) -MMD -MP -c $< -o $@

$(ARM_BUILD)/bench/gen/%.o: $(ARM_BUILD)/gen/%.c $(FW_STAMP)
	@mkdir -p $(dir $@)
	$(ARM_CC) $(ARM_CPPFLAGS) $(ARM_CFLAGS) -c $< -o $@

$(ARM_LIB): $(ARM_CORE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(ARM_AR) rcs $@ $^

$(FW_ELF): $(FW_OBJ) $(ARM_LIB) port/cortex-m/ld/cortex-m4f.ld port/cortex-m/ld/fnav_cm_sections.ld $(FW_STAMP)
	$(ARM_CC) $(ARM_LDFLAGS) -Tcortex-m4f.ld -Wl,--defsym=_stack_size=$(FW_STACK_SIZE) \
	  -Wl,-Map=$(ARM_BUILD)/footnav-fw.map -o $@ $(FW_OBJ) $(ARM_LIB) $(ARM_LDLIBS)

$(FW_SLICE_GEN): port/cortex-m/tools/fw_slice.c $(HXLIB) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_HOST) -o $@ $< $(HXLIB) $(LIB) $(LDLIBS_HOST)

$(FW_SLICE_C): $(FW_SLICE_GEN) $(FW_SLICE_LOG) $(FW_STAMP)
	@mkdir -p $(dir $@)
	$(FW_SLICE_GEN) $(FW_SLICE_LOG) $(FW_SLICE_FIRST) $(FW_SLICE_COUNT) $@ $(FW_SLICE_BIN)

$(BENCH_ELF): $(FWBENCH_OBJ) $(ARM_LIB) port/cortex-m/ld/mps2-an386.ld port/cortex-m/ld/fnav_cm_sections.ld
	$(ARM_CC) $(ARM_LDFLAGS) -Tmps2-an386.ld -Wl,-Map=$(ARM_BUILD)/footnav-bench.map -o $@ $(FWBENCH_OBJ) $(ARM_LIB) $(ARM_LDLIBS)

# The benchmark's code built for the host (float32 core), the reference the
# emulator's output is compared with.
$(FW_HOSTREF): $(FWBENCH_SRC) $(FW_SLICE_C) $(CORE_SRC) $(FW_STAMP) port/cortex-m/fnav_cm_fw_config.h
	@mkdir -p $(dir $@)
	$(CC) -Iinclude -Iport/cortex-m $(FW_CONFIG) $(FW_DEFS) $(CFLAGS_CORE) -o $@ \
	  $(filter-out port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_fault.c,$(FWBENCH_SRC)) $(FW_SLICE_C) $(CORE_SRC) -lm

firmware: $(ARM_LIB) $(FW_ELF)
	@if $(ARM_NM) -u $(ARM_LIB) | grep -E -w '$(FORBIDDEN)'; then \
	  echo "firmware: the core references the symbols above"; exit 1; fi
	@if $(ARM_NM) $(FW_ELF) | grep -E -w 'malloc|_malloc_r|free|_free_r|calloc|realloc|_sbrk|_sbrk_r|printf|_printf_r|puts|fwrite|_write'; then \
	  echo "firmware: the image contains the symbols above (no heap, no stdio allowed)"; exit 1; fi
	@echo "firmware: Cortex-M4F core library $(ARM_LIB) (text = flash, data+bss = RAM):"
	@$(ARM_SIZE) -t $(ARM_LIB) | tail -n 1
	@sz=0; sk=0; sh port/cortex-m/tools/fw_size.sh $(ARM_SIZE) $(FW_ELF) $(FW_FLASH_BUDGET) $(FW_RAM_BUDGET) || sz=1; \
	  $(PYTHON) port/cortex-m/tools/stack_report.py --elf $(FW_ELF) --objdump $(ARM_OBJDUMP) \
	    --indirect port/cortex-m/tools/indirect_calls.txt --reserve-symbol _stack_size --nm $(ARM_NM) \
	    $(addprefix --priority ,$(FW_STACK_PRIORITIES)) --at-least fnav_cm_imu_read=$(FW_IMU_READ_ROOM) \
	    $(patsubst %.o,%.ci,$(FW_OBJ) $(ARM_CORE_OBJ)) || sk=1; \
	  if [ $$sz -ne 0 ] || [ $$sk -ne 0 ]; then echo "firmware: FAILED (budget or stack, see above)"; exit 1; fi

firmware-bench: $(BENCH_ELF) $(FW_HOSTREF) $(HARNESS)
	@if $(ARM_NM) $(BENCH_ELF) | grep -E -w 'malloc|_malloc_r|_sbrk|_sbrk_r|printf|_printf_r'; then \
	  echo "firmware-bench: the image contains the symbols above"; exit 1; fi
	@echo "firmware-bench: $(QEMU) $(QEMU_FLAGS) -kernel $(BENCH_ELF)"
	@timeout 600 $(QEMU) $(QEMU_FLAGS) -kernel $(BENCH_ELF) >$(ARM_BUILD)/bench.txt; st=$$?; \
	  grep -v -E '^(nav|allan|welch) ' $(ARM_BUILD)/bench.txt; \
	  if [ $$st -ne 0 ]; then echo "firmware-bench: the emulator run failed (status $$st)"; exit 1; fi
	@$(FW_HOSTREF) >$(ARM_BUILD)/bench-host.txt || { cat $(ARM_BUILD)/bench-host.txt; \
	  echo "firmware-bench: the host build of the benchmark failed"; exit 1; }
	@rm -f $(ARM_BUILD)/bench-replay.csv; $(HARNESS) replay $(FW_SLICE_BIN) --out $(ARM_BUILD)/bench-replay.csv \
	  >$(ARM_BUILD)/bench-replay.txt 2>&1; st=$$?; \
	  if [ $$st -ne 0 ] && [ $$st -ne 4 ]; then cat $(ARM_BUILD)/bench-replay.txt; \
	  echo "firmware-bench: harness replay of the slice failed (status $$st)"; exit 1; fi
	@$(PYTHON) port/cortex-m/tools/bench_compare.py $(ARM_BUILD)/bench.txt $(ARM_BUILD)/bench-host.txt \
	  --replay $(ARM_BUILD)/bench-replay.csv
	@sh tests/m4/ticks.sh
	@sh tests/m4/wait.sh
	@sh tests/m4/exit.sh
	@MAKE='$(MAKE)' sh tests/m4/stack.sh

# ---------------------------------------------------------------- bench
bench: $(HARNESS) $(BENCH_BINS)
	@set -e; if [ -z "$(BENCH_BINS)" ]; then echo "bench: no benchmarks yet"; fi; \
	for b in $(BENCH_BINS); do echo "== $$b"; $$b; done

# ---------------------------------------------------------------- simgap
# make simgap-validation: the sim-to-real gap diagnosis on cases whose effect
# is withheld (docs/simgap.md), written to docs/simgap-validation.md; the
# per-case JSON goes to $(BUILD)/simgap-validation.json. Niced: it takes
# minutes (the time is in the output).
# A second run of controls only (no effect: static and walk in turn) bounds
# the false-alarm rate better than the few controls of the first.
SIMGAP_CASES ?= 40
SIMGAP_SEED  ?= 1
SIMGAP_CONTROLS ?= 20
# Case i of --seed S owns the seeds S + 20000 i ... S + 20000 i + 19999
# (harness/hx_simgap_valid.h, SGV_SEED_STRIDE). The controls' seed is derived,
# SIMGAP_SEED + SIMGAP_CASES x 20000 (mod 2^32, as the harness's seeds wrap):
# the first seed past the first run's cases (800001 with the defaults,
# 1 + 40 x 20000), so that no control shares a twin or a log's noise with a
# case of the first run whatever SIMGAP_CASES and SIMGAP_SEED are
# (tests/test_simgap.c, test_validate_case_seeds_disjoint;
# tests/cli/test_simgap_validate.sh checks the derivation with make -n).
SIMGAP_CONTROLS_SEED ?= $(shell echo $$(( ($(SIMGAP_SEED) + $(SIMGAP_CASES) * 20000) % 4294967296 )))
simgap-validation: $(HARNESS)
	nice $(HARNESS) simgap-validate --cases $(SIMGAP_CASES) --seed $(SIMGAP_SEED) \
	  --json $(BUILD)/simgap-validation.json --markdown docs/simgap-validation.md
	nice $(HARNESS) simgap-validate --effects control --cases $(SIMGAP_CONTROLS) --seed $(SIMGAP_CONTROLS_SEED) \
	  --json $(BUILD)/simgap-validation-controls.json --markdown docs/simgap-validation-controls.md

# ---------------------------------------------------------------- robustness
# libFuzzer targets tests/fuzz/fuzz_<name>.c, each run for FUZZ_SECONDS on a
# working copy of its committed seed corpus tests/fuzz/corpus/<name>/ under
# ASan + UBSan; any crash, leak, timeout or sanitizer report fails the target.
FUZZ_SECONDS ?= 60
FUZZ_CC   ?= clang
FUZZ_DIR  := build/fuzz
FUZZ_SRC  := $(wildcard tests/fuzz/fuzz_*.c)
FUZZ_BINS := $(FUZZ_SRC:tests/fuzz/%.c=$(FUZZ_DIR)/%)
FUZZ_CFLAGS := -g -O1 -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all \
               -std=c99 -Wall -Wextra -Werror -D_POSIX_C_SOURCE=200809L
FUZZ_LIB_OBJ := $(patsubst %.c,$(FUZZ_DIR)/obj/%.o,$(CORE_SRC) $(HX_SRC))

.SECONDARY: $(FUZZ_LIB_OBJ)

$(FUZZ_DIR)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(CPPFLAGS) $(FUZZ_CFLAGS) -MMD -MP -c $< -o $@

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_LIB_OBJ)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(CPPFLAGS) -Itests/fuzz $(FUZZ_CFLAGS) -MMD -MP -fsanitize=fuzzer $(filter %.c %.o,$^) -o $@ $(LDLIBS_HOST)

fuzz: $(FUZZ_BINS)
	@set -e; for b in $(FUZZ_BINS); do n=$${b#$(FUZZ_DIR)/fuzz_}; \
	  mkdir -p $(FUZZ_DIR)/corpus/$$n $(FUZZ_DIR)/artifacts/$$n; \
	  cp -n tests/fuzz/corpus/$$n/* $(FUZZ_DIR)/corpus/$$n/ 2>/dev/null || true; \
	  echo "== fuzz $$n for $(FUZZ_SECONDS) s"; \
	  $$b -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_DIR)/artifacts/$$n/ $(FUZZ_DIR)/corpus/$$n 2>&1 | tail -n 12; \
	  if ls $(FUZZ_DIR)/artifacts/$$n/* >/dev/null 2>&1; then echo "fuzz $$n: FAILED, see $(FUZZ_DIR)/artifacts/$$n"; exit 1; fi; \
	done; echo "make fuzz: no crash, leak, timeout or sanitizer report"

# Long-run numerical health: LONGRUN_HOURS of simulated walking through the
# float32 navigator (tests/longrun_nav.c); about 1.5 minutes for 10 hours.
LONGRUN_HOURS ?= 10
longrun: $(BUILD)/tests/longrun_nav
	$(BUILD)/tests/longrun_nav $(LONGRUN_HOURS)

# Every suite under valgrind's memcheck (leaks and invalid accesses are errors).
valgrind: $(TEST_BINS)
	@set -e; for t in $(TEST_BINS); do echo "== valgrind $$t"; \
	  valgrind -q --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite,indirect $$t; done
	@echo "make valgrind: clean"

# Static analysis of src/ and port/ with the committed configurations
# (.clang-tidy, tests/cppcheck-suppressions.txt).
lint:
	cppcheck --std=c99 --enable=warning,style,performance,portability --inline-suppr --error-exitcode=1 \
	  --suppressions-list=tests/cppcheck-suppressions.txt -UFNAV_CONFIG_FILE -Iinclude -Iport/linux -Iport/cortex-m -Iharness \
	  --quiet src port
	clang-tidy --quiet $(wildcard src/*.c) $(wildcard port/linux/*.c) $(wildcard port/cortex-m/*.c) -- \
	  $(CPPFLAGS) -std=c99 -D_POSIX_C_SOURCE=200809L
	@echo "make lint: cppcheck and clang-tidy clean"

# ---------------------------------------------------------------- install
# make install: for a program of your own on Linux (README, "Using the
# library in your own program"): libfootnav.a in LIBDIR, the public headers
# in INCLUDEDIR/footnav/ (#include "footnav/footnav.h"), footnav.pc in
# PKGCONFIGDIR and bin/harness in BINDIR as footnav-harness. DESTDIR stages
# the whole tree (packaging); make uninstall removes exactly those files,
# and INCLUDEDIR/footnav once empty. The port is the program's: no port
# header or source is installed (port/linux belongs to the harness;
# docs/firmware.md, "Porting to a new board").
# footnav.pc carries FNAV_DEFS in its Cflags: a program must see the options
# the library was built with (make install FNAV_DEFS=-DFNAV_USE_DOUBLE=1
# rebuilds $(BUILD) in double and says so in footnav.pc). -D options only:
# an FNAV_CONFIG_FILE header is not installed.
PREFIX       ?= /usr/local
EXEC_PREFIX  ?= $(PREFIX)
BINDIR       ?= $(EXEC_PREFIX)/bin
LIBDIR       ?= $(EXEC_PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
INSTALL      ?= install
INSTALL_PROGRAM ?= $(INSTALL)
INSTALL_DATA ?= $(INSTALL) -m 644
HARNESS_NAME ?= footnav-harness
# footnav.pc's Version: by default the one of include/footnav/fnav_version.h
# (FNAV_VERSION_MAJOR.MINOR.PATCH, the version's one source); a packager may
# set VERSION= all the same.
fnav_header_version := $(shell awk '$$2 == "FNAV_VERSION_MAJOR" { a = $$3 } $$2 == "FNAV_VERSION_MINOR" { b = $$3 } \
  $$2 == "FNAV_VERSION_PATCH" { c = $$3 } END { if (a != "" && b != "" && c != "") print a "." b "." c }' \
  include/footnav/fnav_version.h)
VERSION      ?= $(fnav_header_version)
HEADERS      := $(wildcard include/footnav/*.h)

# A path may hold a space, but not a ', a # or a tab: the recipes quote the
# paths with ', and footnav.pc cannot carry a # (a comment to pkg-config) or
# a tab (pkg-config prints a space for it; make's patsubst splits there). make install and make
# uninstall refuse such a path before building or installing anything.
pc_empty :=
fnav_hash := \#
fnav_tab := $(pc_empty)	$(pc_empty)
fnav_install_vars := DESTDIR PREFIX EXEC_PREFIX BINDIR LIBDIR INCLUDEDIR PKGCONFIGDIR HARNESS_NAME
# $(call fnav_refuse,VAR,CHAR,NAME): a make error when $(VAR) holds CHAR
fnav_refuse = $(if $(findstring $(2),$($(1))),$(error make $(fnav_goal): $(1) holds $(3) ($(1)=$($(1))): \
  not supported; a path may hold a space but not a ' or $(fnav_hash) or a tab (the recipes quote paths with ' \
  and footnav.pc cannot carry the other two)))
fnav_goal = $(firstword $(filter install uninstall,$(MAKECMDGOALS)))
ifneq ($(fnav_goal),)
$(foreach v,$(fnav_install_vars),$(call fnav_refuse,$(v),',an apostrophe (')))
$(foreach v,$(fnav_install_vars),$(call fnav_refuse,$(v),$(fnav_hash),a hash ($(fnav_hash))))
$(foreach v,$(fnav_install_vars),$(call fnav_refuse,$(v),$(fnav_tab),a tab))
endif

# A directory under PREFIX is written relative to ${prefix} in footnav.pc,
# so that pkg-config --define-prefix can move the tree. pkg-config splits
# values at blanks: a space in a path is written "\ " (pkg-config keeps the
# backslash in its output, -I/opt/my\ dir/include, for the shell that reads
# the command line), and is hidden from patsubst, which splits at blanks too.
pc_space := $(pc_empty) $(pc_empty)
pc_hide = $(subst $(pc_space),<fnav-space>,$(1))
pc_dir = $(subst <fnav-space>,\ ,$(patsubst $(call pc_hide,$(PREFIX))/%,$${prefix}/%,$(call pc_hide,$(1))))
define FOOTNAV_PC
prefix=$(subst $(pc_space),\ ,$(PREFIX))
libdir=$(call pc_dir,$(LIBDIR))
includedir=$(call pc_dir,$(INCLUDEDIR))

Name: footnav
Description: foot-mounted IMU navigation: strapdown, UKF with zero-velocity updates, Allan deviation, Welch PSD
Version: $(VERSION)
Cflags: -I$${includedir}$(if $(strip $(FNAV_DEFS)), $(strip $(FNAV_DEFS)))
Libs: -L$${libdir} -lfootnav -lm
endef

install: all
	$(file >$(BUILD)/footnav.pc,$(FOOTNAV_PC))
	$(INSTALL) -d '$(DESTDIR)$(LIBDIR)' '$(DESTDIR)$(PKGCONFIGDIR)' '$(DESTDIR)$(INCLUDEDIR)/footnav' '$(DESTDIR)$(BINDIR)'
	$(INSTALL_DATA) '$(LIB)' '$(DESTDIR)$(LIBDIR)/libfootnav.a'
	$(INSTALL_DATA) $(foreach h,$(HEADERS),'$(h)') '$(DESTDIR)$(INCLUDEDIR)/footnav'
	$(INSTALL_DATA) '$(BUILD)/footnav.pc' '$(DESTDIR)$(PKGCONFIGDIR)/footnav.pc'
	$(INSTALL_PROGRAM) '$(HARNESS)' '$(DESTDIR)$(BINDIR)/$(HARNESS_NAME)'

uninstall:
	rm -f '$(DESTDIR)$(LIBDIR)/libfootnav.a' '$(DESTDIR)$(PKGCONFIGDIR)/footnav.pc' '$(DESTDIR)$(BINDIR)/$(HARNESS_NAME)'
	rm -f $(foreach h,$(notdir $(HEADERS)),'$(DESTDIR)$(INCLUDEDIR)/footnav/$(h)')
	@if [ -d '$(DESTDIR)$(INCLUDEDIR)/footnav' ]; then rmdir '$(DESTDIR)$(INCLUDEDIR)/footnav' 2>/dev/null || \
	  echo "uninstall: $(DESTDIR)$(INCLUDEDIR)/footnav holds other files, left in place"; fi

# ---------------------------------------------------------------- misc
deps:
	sh scripts/bootstrap.sh

run: all
	$(HARNESS) replay vectors/walk.bin

clean:
	rm -rf build bin

-include $(shell find build -name '*.d' 2>/dev/null)
