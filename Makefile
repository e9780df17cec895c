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
CPPFLAGS := -Iinclude -Iport/linux -Iharness $(FNAV_DEFS)
CFLAGS_CORE := $(WARN) $(OPT) $(SAN)
# The harness, the Linux port and the tests may use POSIX.
CFLAGS_HOST := $(WARN) $(OPT) $(SAN) -D_POSIX_C_SOURCE=200809L
LDLIBS_HOST := -lcjson -lgsl -lgslcblas -lserialport -lz -lm
LDLIBS_TEST := -lcmocka $(LDLIBS_HOST)

CORE_SRC    := $(wildcard src/*.c)
HX_SRC      := $(filter-out harness/main.c,$(wildcard harness/*.c)) $(wildcard port/linux/*.c)
TEST_SRC    := $(wildcard tests/test_*.c)
BENCH_SRC   := $(wildcard tests/bench_*.c)
TESTHELP_SRC:= $(wildcard tests/support/*.c)

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
        firmware bench deps clean run

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

# The port (in HXLIB) provides fnav_port_assert_failed for the core (LIB):
# HXLIB is named again after LIB so that single-pass linking resolves it.
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
ARM_CFLAGS := $(ARM_ARCH) -Os -g -ffunction-sections -fdata-sections -fstack-usage $(WARN)
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

# ---------------------------------------------------------------- misc
deps:
	sh scripts/bootstrap.sh

run: all
	$(HARNESS) replay vectors/walk.bin

clean:
	rm -rf build bin

-include $(shell find build -name '*.d' 2>/dev/null)
