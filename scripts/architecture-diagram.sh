#!/usr/bin/env bash
# Regenerates docs/images/architecture/architecture.svg (the picture in docs/architecture.md)
# from its Graphviz source, architecture.dot next to it. Installs graphviz when it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! dpkg-query -W -f='${Status}' graphviz 2>/dev/null | grep -q "install ok installed"; then
  echo "architecture-diagram: installing graphviz"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends graphviz
fi

dir=docs/images/architecture
dot -Tsvg "$dir/architecture.dot" -o "$dir/architecture.svg"
echo "architecture-diagram: wrote $dir/architecture.svg"
