# Shared by scripts/test and scripts/bench: a throwaway PostgreSQL server for
# the store's tests, in a temporary directory of its own: initdb as an
# unprivileged user (the Debian package's "postgres" when we are root), a unix
# socket in that directory and a loopback TCP port of its own, scram-sha-256
# passwords and TLS with a certificate made here. pg_test_start exports
# PUPITRE_TEST_PG (a conninfo without password), PGPASSFILE (the password, in
# a file only we read) and PUPITRE_TEST_PG_CTL (how the fault tests stop and
# start it); pg_test_stop stops it and removes the directory.
# SPDX-License-Identifier: GPL-3.0-or-later

PUPITRE_PG_DIR=""

pg_test_bindir() {
    local d
    for d in /usr/lib/postgresql/*/bin; do
        [ -x "$d/initdb" ] && { echo "$d"; return 0; }
    done
    return 1
}

# A TCP port nobody listens on: the kernel picks it.
pg_test_free_port() {
    python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}

# Runs a command as the server's owner: ourselves, or postgres when we are root.
pg_test_as_owner() {
    if [ "$(id -u)" = 0 ]; then
        setpriv --reuid=postgres --regid=postgres --init-groups -- "$@"
    else
        "$@"
    fi
}

pg_test_start() {
    local bin port pw
    bin=$(pg_test_bindir) || { echo "PostgreSQL server not installed" >&2; return 1; }
    command -v openssl >/dev/null || { echo "openssl not installed" >&2; return 1; }
    PUPITRE_PG_DIR=$(mktemp -d "${TMPDIR:-/tmp}/pupitre-pg.XXXXXX")
    chmod 755 "$PUPITRE_PG_DIR"
    mkdir "$PUPITRE_PG_DIR/data" "$PUPITRE_PG_DIR/run"
    [ "$(id -u)" = 0 ] && chown postgres:postgres "$PUPITRE_PG_DIR/data" "$PUPITRE_PG_DIR/run"
    pw=$(head -c 18 /dev/urandom | base64 | tr -d '/+=')
    printf '%s\n' "$pw" >"$PUPITRE_PG_DIR/pw"
    [ "$(id -u)" = 0 ] && chown postgres "$PUPITRE_PG_DIR/pw"
    pg_test_as_owner "$bin/initdb" -D "$PUPITRE_PG_DIR/data" -U pupitre_admin \
        --pwfile="$PUPITRE_PG_DIR/pw" --auth-local=scram-sha-256 --auth-host=scram-sha-256 \
        -E UTF8 --locale=C.UTF-8 >"$PUPITRE_PG_DIR/initdb.log" 2>&1 || {
        cat "$PUPITRE_PG_DIR/initdb.log" >&2
        return 1
    }
    rm -f "$PUPITRE_PG_DIR/pw"
    # TLS with a certificate made here: the tests ask sslmode=require over TCP.
    openssl req -new -x509 -days 2 -nodes -subj "/CN=localhost" \
        -keyout "$PUPITRE_PG_DIR/data/server.key" -out "$PUPITRE_PG_DIR/data/server.crt" \
        >/dev/null 2>&1
    chmod 600 "$PUPITRE_PG_DIR/data/server.key"
    [ "$(id -u)" = 0 ] && chown postgres:postgres "$PUPITRE_PG_DIR/data/server.key" \
        "$PUPITRE_PG_DIR/data/server.crt"
    port=$(pg_test_free_port)
    cat >>"$PUPITRE_PG_DIR/data/postgresql.conf" <<EOF
listen_addresses = '127.0.0.1'
port = $port
unix_socket_directories = '$PUPITRE_PG_DIR/run'
ssl = on
password_encryption = 'scram-sha-256'
max_connections = 120
fsync = off
log_min_messages = warning
EOF
    PUPITRE_TEST_PG_CTL="$bin/pg_ctl -D $PUPITRE_PG_DIR/data -l $PUPITRE_PG_DIR/run/server.log -w -t 30"
    pg_test_as_owner $PUPITRE_TEST_PG_CTL start >/dev/null || {
        cat "$PUPITRE_PG_DIR/run/server.log" >&2
        return 1
    }
    # The password in a file only we (the tests) read, as libpq's ~/.pgpass does.
    printf '*:*:*:pupitre_admin:%s\n' "$pw" >"$PUPITRE_PG_DIR/pgpass"
    chmod 600 "$PUPITRE_PG_DIR/pgpass"
    export PGPASSFILE="$PUPITRE_PG_DIR/pgpass"
    export PUPITRE_TEST_PG="host=127.0.0.1 port=$port user=pupitre_admin dbname=postgres sslmode=require connect_timeout=5"
    export PUPITRE_TEST_PG_SOCKET="$PUPITRE_PG_DIR/run"
    export PUPITRE_TEST_PG_CTL
    # The fault tests run pg_ctl as the server's owner.
    if [ "$(id -u)" = 0 ]; then
        export PUPITRE_TEST_PG_AS="setpriv --reuid=postgres --regid=postgres --init-groups --"
    else
        export PUPITRE_TEST_PG_AS=""
    fi
}

pg_test_stop() {
    [ -n "$PUPITRE_PG_DIR" ] || return 0
    if [ -f "$PUPITRE_PG_DIR/data/postmaster.pid" ]; then
        pg_test_as_owner $PUPITRE_TEST_PG_CTL stop -m immediate >/dev/null 2>&1 || true
    fi
    rm -rf "$PUPITRE_PG_DIR"
    PUPITRE_PG_DIR=""
}
