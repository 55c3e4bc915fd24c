#!/usr/bin/env bash
# Regenerates src/halfspace/gauss_rule_tables.f90: the Gauss-Legendre rules and product-log
# weights that singular_quadrature::new_gauss_tables computes, embedded as constants so that a
# run does not compute them (example/gauss_tables_source.f90 writes the module). Run after
# changing new_gauss_tables, n_max or n_log; the test station_displacement/embedded_gauss_tables_match
# fails while the module and the computed tables differ.
set -euo pipefail
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null
bin=$(fpm run --profile release --example gauss_tables_source --runner echo 2>/dev/null | tail -n 1)
out=src/halfspace/gauss_rule_tables.f90
"$bin" >"$out.new"
mv "$out.new" "$out"
echo "embed_gauss_tables: wrote $out ($(wc -l <"$out") lines)"
