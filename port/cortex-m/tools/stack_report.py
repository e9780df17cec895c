#!/usr/bin/env python3
"""Worst-case stack per entry point of a Cortex-M image (make firmware).

Frame sizes come from GCC's -fcallgraph-info=su files (.ci: one node per
function with its -fstack-usage size, edges for the calls GCC saw, and an
"__indirect_call" placeholder for calls through pointers). The code that
GCC did not compile for us (newlib's libm/libc, libgcc helpers) and the
calls GCC emits late (memcpy for struct copies, __aeabi_* helpers) are
taken from the disassembly of the linked image: every BL/B.W to another
function symbol is a call edge, and a function without a .ci node gets a
conservative frame: the sum of every PUSH/STMDB/VPUSH/SUB SP in its body.

Indirect calls must be resolved by a table (CALLER: TARGET ...); an
unlisted indirect call, a recursion or an unbounded dynamic frame fails.

Entry points: Reset_Handler (thread mode: reset -> main loop) and every
exception handler of the image. The total assumes one interrupt level (all
configurable interrupts share one priority, as in the reference firmware):
thread-mode worst case + the deepest handler + one exception frame with FPU
context (26 words = 104 bytes, ARMv7-M ARM B1.5.7). It is compared with the
stack reserved by the linker script (--reserve-symbol).

usage: stack_report.py --elf ELF --objdump TOOL --nm TOOL --indirect FILE
                       [--reserve-symbol SYM] CI-FILE...
"""
import argparse
import re
import subprocess
import sys

FP_EXCEPTION_FRAME = 104


def parse_ci(paths):
    frames, dynamic, indirect, edges = {}, set(), set(), set()
    node_re = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
    edge_re = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
    for p in paths:
        try:
            text = open(p).read()
        except OSError as e:
            sys.exit('stack_report: cannot read %s: %s' % (p, e))
        title_to_name = {}
        for m in node_re.finditer(text):
            # a weak or static function's title may be "file:name"; the
            # label's first line is the plain name
            name, label = m.group(2).split('\\n', 1)[0], m.group(2)
            title_to_name[m.group(1)] = name
            sm = re.search(r'\\n(\d+) bytes \(([a-z,]+)\)', label)
            if not sm:
                continue  # external function: no size here
            size, kind = int(sm.group(1)), sm.group(2)
            if kind == 'dynamic':
                dynamic.add(name)
            frames[name] = max(frames.get(name, 0), size)
        for m in edge_re.finditer(text):
            src = title_to_name.get(m.group(1), m.group(1))
            if m.group(2) == '__indirect_call':
                indirect.add(src)
            else:
                edges.add((src, title_to_name.get(m.group(2), m.group(2).split(':')[-1])))
    return frames, dynamic, indirect, edges


REGLIST = re.compile(r'\{([^}]*)\}')


def reg_count(lst):
    n = 0
    for part in lst.split(','):
        part = part.strip()
        if not part:
            continue
        m = re.match(r'([rsd])(\d+)\s*-\s*[rsd](\d+)$', part)
        if m:
            k = int(m.group(3)) - int(m.group(2)) + 1
            n += k * (8 if m.group(1) == 'd' else 4)
        elif part.startswith('d'):
            n += 8
        else:
            n += 4
    return n


def parse_objdump(tool, elf):
    out = subprocess.run([tool, '-d', '--no-show-raw-insn', elf], capture_output=True, text=True, check=True).stdout
    funcs = {}  # name -> {'frame': int, 'calls': set, 'indirect': bool}
    cur = None
    head = re.compile(r'^([0-9a-f]+) <([^>]+)>:$')
    insn = re.compile(r'^\s+[0-9a-f]+:\s+([a-z][a-z0-9.]*)\s*(.*)$')
    for line in out.splitlines():
        m = head.match(line)
        if m:
            cur = funcs.setdefault(m.group(2), {'frame': 0, 'calls': set(), 'indirect': False})
            cur_name = m.group(2)
            continue
        if cur is None:
            continue
        m = insn.match(line)
        if not m:
            continue
        op, args = m.group(1), m.group(2)
        base = op.split('.')[0]
        if base in ('push', 'vpush') or (base in ('stmdb', 'vstmdb') and args.startswith('sp!')):
            r = REGLIST.search(args)
            if r:
                cur['frame'] += reg_count(r.group(1))
        elif base in ('sub', 'subw') and re.match(r'sp,\s*(sp,\s*)?#', args):
            cur['frame'] += int(re.search(r'#(\d+)', args).group(1))
        elif base in ('bl', 'b') or re.match(r'^b(eq|ne|cs|cc|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)$', base):
            t = re.search(r'<([^>+]+)(\+0x[0-9a-f]+)?>', args)
            # a BL to a function's entry is a call (to itself: recursion); a
            # plain branch to another function's entry is a tail call; a
            # branch inside the function is neither
            if t and t.group(2) is None and (base == 'bl' or t.group(1) != cur_name):
                cur['calls'].add(t.group(1))
        elif base == 'blx' and not args.startswith('<'):
            cur['indirect'] = True
        elif base == 'bx' and args.strip() != 'lr':
            cur['indirect'] = True
    return funcs


def parse_indirect(path):
    table = {}
    for line in open(path):
        line = line.split('#', 1)[0].strip()
        if not line:
            continue
        caller, _, targets = line.partition(':')
        table[caller.strip()] = targets.split()
    return table


def symbol_value(nm, elf, sym):
    out = subprocess.run([nm, elf], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == sym:
            return int(parts[0], 16)
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--elf', required=True)
    ap.add_argument('--objdump', required=True)
    ap.add_argument('--nm', required=True)
    ap.add_argument('--indirect', required=True)
    ap.add_argument('--reserve-symbol')
    ap.add_argument('ci', nargs='*')
    a = ap.parse_args()

    ci_frames, dynamic, ci_indirect, ci_edges = parse_ci(a.ci)
    funcs = parse_objdump(a.objdump, a.elf)
    table = parse_indirect(a.indirect)
    errors = []

    frame, calls, source = {}, {}, {}
    for name, f in funcs.items():
        if name in ci_frames:
            frame[name], source[name] = ci_frames[name], 'su'
        else:
            frame[name], source[name] = f['frame'], 'asm'
        calls[name] = set(c for c in f['calls'] if c in funcs)
        if f['indirect'] or name in ci_indirect:
            if name not in table:
                errors.append('%s calls through a pointer and is not in %s' % (name, a.indirect))
            else:
                for t in table[name]:
                    if t in funcs:
                        calls[name].add(t)
    for src, dst in ci_edges:  # calls GCC saw (the disassembly has them too, unless inlined away)
        if src in funcs and dst in funcs:
            calls[src].add(dst)
    for name in dynamic:
        if name in funcs:
            errors.append('%s has an unbounded dynamic stack frame' % name)

    memo, path_of = {}, {}

    def worst(name, stack):
        if name in memo:
            return memo[name]
        if name in stack:
            errors.append('recursion: %s' % ' -> '.join(stack[stack.index(name):] + [name]))
            return 0
        best, best_path = 0, []
        for c in sorted(calls.get(name, ())):
            w = worst(c, stack + [name])
            if w > best:
                best, best_path = w, path_of.get(c, [c])
        memo[name] = frame.get(name, 0) + best
        path_of[name] = [name] + best_path
        return memo[name]

    entries = ['Reset_Handler'] + sorted(
        n for n in funcs
        if n != 'Reset_Handler' and (n.endswith('_Handler') or n.endswith('_IRQHandler') or n == 'fnav_cm_default_handler'))
    entries = [e for e in entries if e in funcs]
    # weak aliases share an address: report each handler name once
    print('stack: worst case per entry point (bytes; su = -fstack-usage, asm = from the disassembly)')
    handler_worst = 0
    for e in entries:
        w = worst(e, [])
        chain = ' > '.join('%s(%d%s)' % (n, frame.get(n, 0), '' if source.get(n) == 'su' else ' asm')
                           for n in path_of[e])
        print('stack: %-28s %5d  %s' % (e, w, chain))
        if e != 'Reset_Handler':
            handler_worst = max(handler_worst, w)
    thread = memo.get('Reset_Handler', 0)
    total = thread + handler_worst + FP_EXCEPTION_FRAME
    print('stack: total worst case = thread %d + deepest handler %d + exception frame with FPU context %d = %d bytes'
          % (thread, handler_worst, FP_EXCEPTION_FRAME, total))
    if a.reserve_symbol:
        reserve = symbol_value(a.nm, a.elf, a.reserve_symbol)
        if reserve is None:
            errors.append('symbol %s not found' % a.reserve_symbol)
        else:
            print('stack: reserved by the linker script: %d bytes (%s)' % (reserve, a.reserve_symbol))
            if total > reserve:
                errors.append('worst-case stack %d exceeds the reserve of %d bytes' % (total, reserve))
    for e in errors:
        print('stack: error: %s' % e)
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
