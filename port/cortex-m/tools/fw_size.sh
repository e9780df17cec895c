#!/bin/sh
# Flash and RAM of a Cortex-M image against a budget (make firmware).
#   fw_size.sh SIZE-TOOL ELF FLASH-BUDGET RAM-BUDGET
# flash = vector table + code + constants + exception index + .data's initial
# values; RAM = .data + .bss + the reserved stack (.stack). Fails when over.
set -eu
SIZE=$1; ELF=$2; FB=$3; RB=$4
"$SIZE" -A "$ELF" | awk -v fb="$FB" -v rb="$RB" -v elf="$ELF" '
    $1 == ".isr_vector" || $1 == ".text" || $1 == ".ARM.exidx" || $1 == ".ARM.extab" { flash += $2 }
    $1 == ".data" { flash += $2; ram += $2; data = $2 }
    $1 == ".bss" { ram += $2; bss = $2 }
    $1 == ".stack" { ram += $2; stack = $2 }
    END {
        printf "firmware: image %s\n", elf
        printf "firmware: flash %6d bytes (%.1f KB) of the %d-byte budget\n", flash, flash / 1024, fb
        printf "firmware: RAM   %6d bytes (%.1f KB) of the %d-byte budget = .data %d + .bss %d + stack reserve %d\n", ram, ram / 1024, rb, data, bss, stack
        bad = 0
        if (flash > fb) { printf "firmware: FLASH OVER BUDGET by %d bytes\n", flash - fb; bad = 1 }
        if (ram > rb) { printf "firmware: RAM OVER BUDGET by %d bytes\n", ram - rb; bad = 1 }
        exit bad
    }'
