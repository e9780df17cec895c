# footnav top-level Makefile.
#
#   make            static library + harness (bin/harness)
#   make test       every CMocka suite (float and double builds), the CLI
#                   tests, the golden-vector cross-checks, the no-allocation check
#   make sanitize   the suites and CLI tests under ASan + UBSan
#   make firmware   the core cross-compiled for Cortex-M4F, with a size report
#   make bench      benchmarks (figures quoted in docs/ come from here)
#   make deps       install the Debian packages (scripts/bootstrap.sh)
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
TESTHELP_SRC:= $(wildcard tests/support/*.c) port/cortex-m/fnav_cm_ring.c

CORE_OBJ    := $(CORE_SRC:%.c=$(BUILD)/obj/%.o)
HX_OBJ      := $(HX_SRC:%.c=$(BUILD)/obj/%.o)
TESTHELP_OBJ:= $(TESTHELP_SRC:%.c=$(BUILD)/obj/%.o)
LIB         := $(BUILD)/libfootnav.a
HXLIB       := $(BUILD)/libhx.a
TEST_BINS   := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCH_BINS  := $(BENCH_SRC:tests/%.c=$(BUILD)/tests/%)

# Symbols no core object may reference: allocation, stdio, process control.
FORBIDDEN := malloc|calloc|realloc|free|_sbrk|sbrk|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|vsnprintf|puts|fputs|putchar|fputc|putc|fopen|fclose|fread|fwrite|fflush|stdout|stderr|stdin|_impure_ptr|__printf_chk|__fprintf_chk|__sprintf_chk|__snprintf_chk|exit|abort|system

.PHONY: all test check-suites test-double test-cli vectors-check nm-check sanitize \
        firmware bench deps clean run fuzz valgrind lint

all: $(LIB) $(HARNESS) nm-check

$(BUILD)/obj/src/%.o: src/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_CORE) -MMD -MP -c $< -o $@

$(BUILD)/obj/%.o: %.c
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

# The core must not allocate, print or exit (checked on every build).
nm-check: $(LIB)
	@if nm -u $(LIB) | grep -E -w '$(FORBIDDEN)'; then \
	  echo "nm-check: the core library references the symbols above (no allocation or libc I/O allowed in src/)"; exit 1; \
	else echo "nm-check: core library is allocation-free and I/O-free"; fi

check-suites: $(TEST_BINS)
	@set -e; for t in $(TEST_BINS); do echo "== $$t"; $$t; done

test-cli: $(HARNESS)
	@set -e; for t in tests/cli/test_*.sh; do echo "== $$t"; HARNESS=$(abspath $(HARNESS)) sh $$t; done

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

# ---------------------------------------------------------------- firmware
ARM_CC    ?= arm-none-eabi-gcc
ARM_AR    ?= arm-none-eabi-ar
ARM_NM    ?= arm-none-eabi-nm
ARM_SIZE  ?= arm-none-eabi-size
ARM_BUILD := build/arm
ARM_ARCH  := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
ARM_CFLAGS := $(ARM_ARCH) -Os -g -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su $(WARN)
ARM_CORE_OBJ := $(CORE_SRC:%.c=$(ARM_BUILD)/obj/%.o)
ARM_PORT_OBJ := $(patsubst %.c,$(ARM_BUILD)/obj/%.o,$(wildcard port/cortex-m/*.c))
ARM_LIB   := $(ARM_BUILD)/libfootnav.a

$(ARM_BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(ARM_CC) -Iinclude -Iport/cortex-m $(ARM_CFLAGS) -MMD -MP -c $< -o $@

$(ARM_LIB): $(ARM_CORE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(ARM_AR) rcs $@ $^

firmware: $(ARM_LIB) $(ARM_PORT_OBJ)
	@if $(ARM_NM) -u $(ARM_LIB) | grep -E -w '$(FORBIDDEN)'; then \
	  echo "firmware: the core references the symbols above"; exit 1; fi
	@echo "firmware: Cortex-M4F core library $(ARM_LIB) (text = flash, data+bss = RAM):"
	@$(ARM_SIZE) -t $(ARM_LIB) | tail -n 1
	@$(ARM_SIZE) $(ARM_PORT_OBJ)

# ---------------------------------------------------------------- bench
bench: $(HARNESS) $(BENCH_BINS)
	@set -e; if [ -z "$(BENCH_BINS)" ]; then echo "bench: no benchmarks yet"; fi; \
	for b in $(BENCH_BINS); do echo "== $$b"; $$b; done

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
	$(FUZZ_CC) $(CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_LIB_OBJ)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(CPPFLAGS) -Itests/fuzz $(FUZZ_CFLAGS) -fsanitize=fuzzer $^ -o $@ $(LDLIBS_HOST)

fuzz: $(FUZZ_BINS)
	@set -e; for b in $(FUZZ_BINS); do n=$${b#$(FUZZ_DIR)/fuzz_}; \
	  mkdir -p $(FUZZ_DIR)/corpus/$$n $(FUZZ_DIR)/artifacts/$$n; \
	  cp -n tests/fuzz/corpus/$$n/* $(FUZZ_DIR)/corpus/$$n/ 2>/dev/null || true; \
	  echo "== fuzz $$n for $(FUZZ_SECONDS) s"; \
	  $$b -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_DIR)/artifacts/$$n/ $(FUZZ_DIR)/corpus/$$n 2>&1 | tail -n 12; \
	  if ls $(FUZZ_DIR)/artifacts/$$n/* >/dev/null 2>&1; then echo "fuzz $$n: FAILED, see $(FUZZ_DIR)/artifacts/$$n"; exit 1; fi; \
	done; echo "make fuzz: no crash, leak, timeout or sanitizer report"

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

# ---------------------------------------------------------------- misc
deps:
	sh scripts/bootstrap.sh

run: all
	$(HARNESS) replay vectors/walk.bin

clean:
	rm -rf build bin

-include $(shell find build -name '*.d' 2>/dev/null)
