# Sourced by tools/ci/spark-cluster-test and tools/studies/spark-measure/run: pyspark 4.1.3 in a
# virtual environment, and a standalone master and two one-core workers on 127.0.0.1, each started as
# a background job of its own process group (the caller runs `set -m`), all stopped by those ids by
# stop_all.
#   needs: fail MESSAGE (the caller's), $work (a folder), $keep (empty: remove $work at the end);
#          $me, the caller's name in messages, if it has one (else the script's file name)
# defines: SPARK_HOME, SPARK_CONF_DIR, $master, $workers (pids), $groups (pids of process groups)

PYSPARK_VERSION=4.1.3
venv=${RAYTRACER_PYSPARK_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/raytracer/pyspark-$PYSPARK_VERSION}

# pyspark installed if missing, SPARK_HOME and SPARK_LOCAL_IP set, the jars built
ensure_spark() {
  if ! "$venv/bin/python" -c "import pyspark, sys; sys.exit(pyspark.__version__ != '$PYSPARK_VERSION')" 2>/dev/null; then
    echo "${me:-$(basename "$0")}: installing pyspark $PYSPARK_VERSION into $venv (about 500 MB)" >&2
    python3 -m venv "$venv" || fail "cannot make a virtual environment in $venv (apt-get install python3-venv?)"
    "$venv/bin/pip" install -q "pyspark==$PYSPARK_VERSION" || fail "cannot install pyspark==$PYSPARK_VERSION from PyPI"
  fi
  SPARK_HOME=$("$venv/bin/python" -c "import os, pyspark; print(os.path.dirname(pyspark.__file__))")
  export SPARK_HOME
  export SPARK_LOCAL_IP=127.0.0.1
  tools/ci/ensure-gradle >/dev/null || fail "gradle is missing and could not be installed"
  gradle -q --console=plain jar sparkJar >/dev/null 2>&1 || fail "gradle jar sparkJar"
  mkdir -p "$work/conf" "$work/logs"
  # Spark's own log at WARN (driver, master, workers and executors read this folder)
  cat > "$work/conf/log4j2.properties" <<'EOF'
rootLogger.level = warn
rootLogger.appenderRef.stderr.ref = stderr
appender.stderr.type = Console
appender.stderr.name = stderr
appender.stderr.target = SYSTEM_ERR
appender.stderr.layout.type = PatternLayout
appender.stderr.layout.pattern = %d{HH:mm:ss} %p %c{1}: %m%n
EOF
  export SPARK_CONF_DIR=$work/conf
}

groups=()
workers=()
stop_all() {
  for pid in "${groups[@]}"; do
    kill -TERM -- "-$pid" 2>/dev/null
  done
  for _ in 1 2 3 4 5 6 7 8 9 10; do
    alive=0
    for pid in "${groups[@]}"; do
      kill -0 -- "-$pid" 2>/dev/null && alive=1
    done
    [ $alive -eq 0 ] && break
    sleep 0.5
  done
  for pid in "${groups[@]}"; do
    kill -KILL -- "-$pid" 2>/dev/null
  done
  if [ -z "$keep" ]; then
    rm -rf "$work"
  fi
}

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# the workers the master counts alive, from its web UI's JSON
alive_workers() {
  python3 -c '
import json, sys, urllib.request
state = json.load(urllib.request.urlopen("http://127.0.0.1:%s/json/" % sys.argv[1], timeout=2))
print(sum(1 for w in state.get("workers", []) if w.get("state") == "ALIVE"))' "$master_ui" 2>/dev/null || echo 0
}

start_cluster() {
  master_port=$(free_port)
  master_ui=$(free_port)
  master=spark://127.0.0.1:$master_port
  "$SPARK_HOME/bin/spark-class" org.apache.spark.deploy.master.Master --host 127.0.0.1 --port "$master_port" \
    --webui-port "$master_ui" > "$work/logs/master.log" 2>&1 &
  groups+=($!)
  for n in 1 2; do
    "$SPARK_HOME/bin/spark-class" org.apache.spark.deploy.worker.Worker --host 127.0.0.1 --cores 1 --memory 1g \
      --work-dir "$work/worker-$n" --webui-port "$(free_port)" "$master" > "$work/logs/worker-$n.log" 2>&1 &
    groups+=($!)
    workers+=($!)
  done
  for _ in $(seq 120); do
    [ "$(alive_workers)" = 2 ] && break
    sleep 0.5
  done
  [ "$(alive_workers)" = 2 ] || fail "the two workers did not register with the master in 60 s (logs in $work/logs)"
  echo "${me:-$(basename "$0")}: a master (${groups[0]}) and two workers (${workers[*]}) of 1 core each on 127.0.0.1" >&2
}
