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
exception handler of the image. Nesting: --priority HANDLER=LEVEL puts a
handler at a preemption level (a higher level preempts a lower one; the
handlers not named are at level 0, where none preempts another, as with
the NVIC's reset priorities). Every level present stacks on the one below
it: the total is the thread's worst case, then for each level from the
lowest an exception frame with FPU context (26 words = 104 bytes, ARMv7-M
ARM B1.5.7; the interrupted code used the FPU) and the level's deepest
handler. Below a preemption (the thread, and every level but the highest)
a depth is rounded up to 8: the frame is 8-byte aligned (CCR.STKALIGN), so
a preemption where the stack is 4 mod 8 adds 4 bytes of padding, and any
depth d preempted at a point x <= d costs at most round8(d). The total is
compared with the stack reserved by the linker script (--reserve-symbol).

--at-least FUNCTION=BYTES counts a function's frame as at least BYTES: room
for a board's function the image holds a stub of (fnav_cm_imu_read, called
in the sample-ready interrupt; the stub's frame is 0). A board linking its
own has it measured as any function, and the larger is counted.

usage: stack_report.py --elf ELF --objdump TOOL --nm TOOL --indirect FILE
                       [--reserve-symbol SYM] [--priority HANDLER=LEVEL]...
                       [--at-least FUNCTION=BYTES]... CI-FILE...
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
    ap.add_argument('--priority', action='append', default=[], metavar='HANDLER=LEVEL')
    ap.add_argument('--at-least', action='append', default=[], metavar='FUNCTION=BYTES')
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

    def pairs(items, what):
        out = {}
        for it in items:
            name, _, val = it.partition('=')
            if not name or not val.isdigit():
                sys.exit('stack_report: --%s %s: expected NAME=NUMBER' % (what, it))
            out[name] = int(val)
        return out

    level_of = pairs(a.priority, 'priority')
    at_least = pairs(a.at_least, 'at-least')
    for name, n in sorted(at_least.items()):
        if name not in funcs:
            errors.append('--at-least %s: no such function in the image' % name)
        elif frame[name] < n:
            frame[name], source[name] = n, 'reserved'

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
    for e in entries:
        w = worst(e, [])
        tag = {'su': '', 'reserved': ' reserved'}
        chain = ' > '.join('%s(%d%s)' % (n, frame.get(n, 0), tag.get(source.get(n), ' asm'))
                           for n in path_of[e])
        print('stack: %-28s %5d  %s' % (e, w, chain))
    for name in level_of:
        if name not in entries:
            errors.append('--priority %s: no such handler in the image' % name)
    levels = {}  # level -> (depth, handler)
    for e in entries:
        if e != 'Reset_Handler':
            lv = level_of.get(e, 0)
            if lv not in levels or memo[e] > levels[lv][0]:
                levels[lv] = (memo[e], e)
    thread = memo.get('Reset_Handler', 0)

    def round8(x):
        return (x + 7) // 8 * 8

    total = round8(thread)
    terms = ['thread %d%s' % (thread, '' if round8(thread) == thread else ' (%d aligned)' % round8(thread))]
    order = sorted(levels)
    for i, lv in enumerate(order):
        depth, name = levels[lv]
        d = depth if i == len(order) - 1 else round8(depth)
        total += FP_EXCEPTION_FRAME + d
        terms.append('frame %d + level %d %s %d%s' % (FP_EXCEPTION_FRAME, lv, name, depth,
                                                       '' if d == depth else ' (%d aligned)' % d))
    print('stack: total worst case, %d interrupt level%s nested = %s = %d bytes'
          % (len(order), '' if len(order) == 1 else 's', ' + '.join(terms), total))
    for name, n in sorted(at_least.items()):
        if name in funcs:
            print('stack: room for %s: %d bytes (--at-least %d; %s)'
                  % (name, frame[name], n, 'the image\'s is smaller: the room counted' if source[name] == 'reserved'
                     else 'the image\'s own frame, measured'))
    if a.reserve_symbol:
        reserve = symbol_value(a.nm, a.elf, a.reserve_symbol)
        if reserve is None:
            errors.append('symbol %s not found' % a.reserve_symbol)
        else:
            print('stack: reserved by the linker script: %d bytes (%s)' % (reserve, a.reserve_symbol))
            if total > reserve:
                errors.append('worst-case stack %d exceeds the reserve of %d bytes by %d' % (total, reserve, total - reserve))
            else:
                print('stack: margin %d bytes' % (reserve - total))
    for e in errors:
        print('stack: error: %s' % e)
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
