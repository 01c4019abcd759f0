#!/usr/bin/env bash
# Lists source files over 500 lines and functions over 80 lines (a brace-matching heuristic
# on clang-formatted code: a function body starts at a line ending in "{" whose previous
# non-blank text closes a parameter list, at namespace level (column 0) or as a class member).
cd "$(dirname "$0")/.."
echo "files over 500 lines:"; find forward inverse reports cli bench tests -name '*.[ch]pp' | xargs wc -l | awk '$1 > 500 && $2 != "total"'
echo "functions over 80 lines:"
for f in $(find forward inverse reports cli bench tests -name '*.[ch]pp'); do
  awk -v F="$f" '
    function count(s, c,   n) { n = gsub(c, "", s); return n }
    {
      line = $0
      if (depth == 0 && start == 0 && line ~ /\)[^;]*\{[ \t]*$/ && line !~ /^(namespace|struct|class|enum|union)/ && line !~ /^[ \t]*(if|for|while|switch|else|do)\b/) { start = NR; name = line }
      o = count(line, "{"); c = count(line, "}")
      if (start) { depth += o - c; if (depth <= 0) { if (NR - start + 1 > 80) printf "%s:%d: %d lines: %s\n", F, start, NR - start + 1, substr(name, 1, 90); start = 0; depth = 0 } }
    }' "$f"
done
