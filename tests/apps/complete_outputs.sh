# Sourced by the fault tests: checks that every output file in a folder is whole.
# usage: check_complete_outputs DIR   (prints what is wrong and returns 1, or returns 0)
check_complete_outputs() {
  local dir=$1 file bad=0
  # temporaries (.<name>.tmp<pid>_<n>) are renamed or removed, never left
  if [ -n "$(find "$dir" -maxdepth 1 -name '.*' -type f)" ]; then
    echo "temporary files left: $(find "$dir" -maxdepth 1 -name '.*' -type f)"; bad=1
  fi
  # stats.csv: a header and whole rows of as many fields (lib/frame_stats.cpp: 25), ending with a
  # newline
  local fields=25
  if [ -e "$dir/stats.csv" ]; then
    if [ -s "$dir/stats.csv" ] && [ "$(tail -c 1 "$dir/stats.csv" | od -An -c | tr -d ' ')" != '\n' ]; then
      echo "stats.csv does not end with a newline"; bad=1
    fi
    if awk -F, -v n=$fields 'NF != n { exit 1 }' "$dir/stats.csv"; then :; else
      echo "stats.csv has a row without $fields fields: $(awk -F, -v n=$fields 'NF != n' "$dir/stats.csv" | head -1)"; bad=1
    fi
  fi
  # OBJ meshes end with their last face line
  for file in "$dir"/frame_*.obj "$dir"/last_good_frame_*.obj; do
    [ -e "$file" ] || continue
    if [ "$(tail -n 1 "$file" | cut -c1-2)" != "f " ] || [ "$(tail -c 1 "$file" | od -An -c | tr -d ' ')" != '\n' ]; then
      echo "$file is cut short: $(tail -c 60 "$file")"; bad=1
    fi
  done
  # frames.pc2: a 32-byte header, then as many whole samples (points x 3 float32) as it counts
  if [ -e "$dir/frames.pc2" ]; then
    local points samples size
    points=$(od -An -t d4 -j 16 -N 4 "$dir/frames.pc2" | tr -d ' ')
    samples=$(od -An -t d4 -j 28 -N 4 "$dir/frames.pc2" | tr -d ' ')
    size=$(stat -c %s "$dir/frames.pc2")
    if [ "$size" -ne $((32 + samples * points * 12)) ]; then
      echo "frames.pc2 holds $size bytes, its header counts $samples samples of $points points"; bad=1
    fi
  fi
  # glTF binaries are as long as their header says (glTF 2.0, "Binary glTF Layout")
  for file in "$dir"/frame_*.glb; do
    [ -e "$file" ] || continue
    if [ "$(od -An -t u4 -j 8 -N 4 "$file" | tr -d ' ')" != "$(stat -c %s "$file")" ]; then
      echo "$file is cut short"; bad=1
    fi
  done
  # PNG images end with their IEND chunk
  for file in "$dir"/frame_*.png; do
    [ -e "$file" ] || continue
    if [ "$(tail -c 12 "$file" | od -An -tx1 | tr -d ' \n')" != "0000000049454e44ae426082" ]; then
      echo "$file is cut short"; bad=1
    fi
  done
  return $bad
}
