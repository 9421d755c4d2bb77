# Sourced by the scripts: the environment of tubeform's runs, as scripts/runs.env lists it (mpirun as root and
# oversubscribed, one OpenBLAS thread per rank, Open MPI's start-up); a variable already set is kept.
while read -r name_value unless path; do
  case "$name_value" in '' | '#'*) continue ;; esac
  name="${name_value%%=*}"
  [ -n "${!name+set}" ] && continue
  [ "$unless" = unless ] && [ -e "$path" ] && continue
  export "$name_value"
done <"$(dirname "${BASH_SOURCE[0]}")/runs.env"
unset name_value unless path name
