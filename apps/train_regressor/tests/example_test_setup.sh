# Sourced by the tests that run on the example's outputs, in the example's folder after
# train_regressor.example, with the arguments TRAIN_REGRESSOR EVALUATE SCRATCH. Sets train,
# evaluate, dataset, scratch (emptied), out and log (for the commands' stdout and stderr), status,
# and fail MESSAGE, which reports MESSAGE with both logs and fails the test.
set -u
train=$1
evaluate=$2
scratch=$3
dataset=train_output/example_dataset
rm -rf "$scratch"
mkdir -p "$scratch"
out="$scratch/stdout.txt"
log="$scratch/stderr.txt"
status=0
fail() {
  echo "$1"
  [ ! -s "$out" ] || { echo "--- stdout ---"; cat "$out"; }
  echo "--- stderr ---"
  cat "$log"
  status=1
}
