#!/usr/bin/env python3
"""ncu_source_summary.py <source.csv>: where a kernel's time goes, from Nsight Compute's source page exported as
`ncu -i <report> --page source --csv --print-source cuda,sass > source.csv` (a report profiled with
`--section SourceCounters --section WarpStateStats --import-source yes` of a program compiled with -lineinfo;
bench/gpu_profile.sh makes both). Prints the average threads busy per warp instruction, the warp stall reasons, the
functions (programs) the stalls fall in, and the shares of issued instructions and stall samples by source file and
by source line (docs/performance.md, 'Where the Cornell box's frame goes')."""
import collections
import csv
import sys

STALL_SAMPLES = "Warp Stall Sampling (All Samples)"
INSTRUCTIONS = "Instructions Executed"
THREAD_INSTRUCTIONS = "Thread Instructions Executed"


def number(text):
    try:
        return int(text)
    except ValueError:
        return 0


def summarise(rows, top):
    path = function = None
    header = None
    stalls, instructions, thread_instructions = (collections.Counter() for _ in range(3))
    by_function, reasons, lines_stalls, line_text = collections.Counter(), collections.Counter(), collections.Counter(), {}
    for row in rows:
        if not row:
            continue
        if row[0] == "File Path":
            path = row[1]
        elif row[0] == "Function Name":
            function = row[1].split("_0x")[0]
        elif row[0] == "Line No":
            header = {name: i for i, name in enumerate(row)}
        elif header and row[0] and len(row) >= len(header):
            # A source line's row: its metrics are the sums over the SASS instructions listed after it.
            s = number(row[header[STALL_SAMPLES]])
            stalls[path] += s
            instructions[path] += number(row[header[INSTRUCTIONS]])
            thread_instructions[path] += number(row[header[THREAD_INSTRUCTIONS]])
            by_function[function] += s
            lines_stalls[(path, row[0])] += s
            line_text[(path, row[0])] = row[1].strip()  # the CUDA line (the page has a second "Source": the SASS)
            for name, i in header.items():
                if name.startswith("stall_") and "(Not Issued)" not in name:
                    reasons[name[len("stall_"):]] += number(row[i])
    total_instructions = sum(instructions.values())
    total_stalls = sum(stalls.values())
    total_reasons = sum(reasons.values())
    if not total_instructions or not total_stalls:
        sys.exit("no source-line metrics in the file: was the report profiled with --section SourceCounters and "
                 "exported with --print-source cuda,sass?")
    print(f"threads per warp instruction: {sum(thread_instructions.values()) / total_instructions:.1f} of 32")
    print("stall reasons: " + ", ".join(f"{name} {100 * v / total_reasons:.0f}%" for name, v in reasons.most_common(8)))
    print("stalls by function: " + ", ".join(f"{name} {100 * v / total_stalls:.0f}%"
                                               for name, v in by_function.most_common(6)))
    print("by source file: instructions issued, stall samples")
    for name, v in instructions.most_common(top):
        print(f"  {100 * v / total_instructions:5.1f}% {100 * stalls[name] / total_stalls:5.1f}%  {name}")
    print("by source line: stall samples")
    for (name, line), v in lines_stalls.most_common(top):
        print(f"  {100 * v / total_stalls:5.1f}%  {name}:{line}  {line_text[(name, line)][:80]}")


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    top = int(sys.argv[2]) if len(sys.argv) == 3 else 15
    with open(sys.argv[1], newline="") as f:
        summarise(csv.reader(f), top)


if __name__ == "__main__":
    main()
