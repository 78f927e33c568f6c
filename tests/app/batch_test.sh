#!/usr/bin/env bash
# docs/batch.md's recipes, run as written: an animation rendered whole, then in shards by
# GNU parallel, then by the Slurm array script with GNU parallel standing in for the array;
# every shard's frame must be byte for byte the whole run's.
# Usage: batch_test.sh ZEROSET SOURCE_DIR WORK_DIR
set -euo pipefail
zeroset=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
export PATH="$(dirname "$zeroset"):$PATH"
common=(x^2+y^2+z^2-a --set params.a=0.5 --animate params.a=0.3:1 --frames 7 --size 40x30)

zeroset render "${common[@]}" -o "$work/whole" > /dev/null
seq 0 2 | parallel --will-cite -j 3 zeroset render "${common[@]}" -o "$work/parallel" \
  --shard {}/3 > /dev/null
seq 3 6 | parallel --will-cite -j 4 \
  SLURM_ARRAY_TASK_ID={} SLURM_ARRAY_TASK_MIN=3 SLURM_ARRAY_TASK_COUNT=4 \
  ZS_SCENE="'x^2+y^2+z^2-1+0.3*sin(3*x)'" ZS_ANIMATE=camera.orbit=0:90 ZS_FRAMES=7 ZS_SIZE=40x30 \
  ZS_OUT="$work/slurm" bash "$source/docs/batch/render-shards.sbatch" > /dev/null
zeroset render "x^2+y^2+z^2-1+0.3*sin(3*x)" --animate camera.orbit=0:90 --frames 7 \
  --size 40x30 -o "$work/slurm-whole" > /dev/null

same() {  # the same file names and bytes in two folders
  local a=$1 b=$2
  [[ $(ls "$a") == $(ls "$b") ]] || { echo "different frames in $a and $b"; exit 1; }
  for f in "$a"/*; do cmp -s "$f" "$b/$(basename "$f")" || { echo "differs: $f"; exit 1; }; done
}
same "$work/whole" "$work/parallel"
same "$work/slurm-whole" "$work/slurm"
echo "shards reassemble exactly: $(ls "$work/whole" | wc -l) + $(ls "$work/slurm" | wc -l) frames"
