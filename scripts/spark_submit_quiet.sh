#!/usr/bin/env bash
# Counts what a Spark render prints on stderr through the real spark-submit script (PyPI's pyspark),
# on a standalone master and worker bound to 127.0.0.1 only (docs/spark.md): the command promises
# its own line alone; spark-submit's JVM may add one warning of its own before the command starts
# ("WARNING: Using incubator modules: jdk.incubator.vector").
#
#   scripts/spark_submit_quiet.sh [VENV]      (VENV default /tmp/raytracer-pyspark; made when absent)
#
# Needs target/raytracer.jar of a build with Spark (mvn -Pspark package) and JDK 17 or 21. Prints one
# line per case: its exit code, stdout and stderr line counts, and stderr's lines other than that
# warning, and for the render the executor's stderr file; exits 1 when a case prints more on stderr
# than its own line, or that file holds more than the worker's header and the warning.
# app.spark.SparkSubmitTest checks the same in mvn verify -Pspark (RAYTRACER_SPARK_HOME; docs/spark.md).
set -euo pipefail
cd "$(dirname "$0")/.."
venv=${1:-/tmp/raytracer-pyspark}
[ -x "$venv/bin/spark-submit" ] || { python3 -m venv "$venv" && "$venv/bin/pip" install -q 'pyspark==4.0.1'; }
export SPARK_HOME=$("$venv/bin/python" -c 'import pyspark, os; print(os.path.dirname(pyspark.__file__))')
export SPARK_LOCAL_IP=127.0.0.1
work=$(mktemp -d)
trap 'kill $worker $master 2>/dev/null || true; rm -rf "$work"' EXIT
"$SPARK_HOME/bin/spark-class" org.apache.spark.deploy.master.Master --host 127.0.0.1 --port 7377 --webui-port 8390 \
    > "$work/master.log" 2>&1 &
master=$!
sleep 6
"$SPARK_HOME/bin/spark-class" org.apache.spark.deploy.worker.Worker spark://127.0.0.1:7377 --host 127.0.0.1 \
    --webui-port 8391 --cores 2 --memory 1g --work-dir "$work/work" > "$work/worker.log" 2>&1 &
worker=$!
sleep 6
status=0
run() { # NAME EXPECTED_EXIT ARGS...
    local name=$1 expected=$2; shift 2
    set +e
    "$SPARK_HOME/bin/spark-submit" --master spark://127.0.0.1:7377 --driver-memory 512m --executor-memory 512m \
        "$@" > "$work/out.txt" 2> "$work/err.txt"
    local code=$?
    set -e
    local own; own=$(grep -vc '^WARNING: Using incubator modules' "$work/err.txt" || true)
    echo "$name: exit $code, stdout $(wc -l < "$work/out.txt") lines, stderr $(wc -l < "$work/err.txt") lines"
    grep -v '^WARNING: Using incubator modules' "$work/err.txt" | sed 's/^/    /' || true
    local allowed=$([ "$expected" = 0 ] && echo 0 || echo 1)
    if [ "$code" != "$expected" ] || [ "$own" -gt "$allowed" ]; then status=1; fi
}
run "teapot 100 tiles" 0 --class app.cli.Main target/raytracer.jar --spark submit scenes/teapot.xml \
    --width 640 --height 640 -o "$work/teapot.png"
# The executor's own stderr, a file the worker keeps: its 3-line header (the command, a rule, a
# blank line) and the JVM's warning, no line of Spark's (371 lines before the executors were quiet).
for f in "$work"/work/*/*/stderr; do
    extra=$(tail -n +4 "$f" | grep -vc '^WARNING: Using incubator modules' || true)
    echo "    executor ${f#"$work"/work/}: $(wc -l < "$f") lines, $extra beyond the worker's header and the JVM's warning"
    if [ "$extra" -gt 0 ]; then status=1; fi
done
run "bad executorTimeout" 2 --conf spark.raytracer.executorTimeout=abc --class app.cli.Main target/raytracer.jar \
    --spark submit scenes/teapot.xml -o "$work/x.png"
kill $worker; wait $worker 2>/dev/null || true
run "no worker left" 1 --conf spark.raytracer.executorTimeout=5s --class app.cli.Main target/raytracer.jar \
    --spark submit scenes/showcase.xml --width 64 --height 64 -o "$work/lost.png"
exit $status
