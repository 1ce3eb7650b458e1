// Inside the store: the class on a PostgreSQL server (pupitre-exercise(5),
// THE CLASS ON A SERVER), as SQL that `pupitre class init` runs once, in one
// transaction, as a teacher (a login with CREATEROLE). It adds to the store's
// tables (schema_pg.hpp) what the server enforces: two group roles, grants,
// row-level security policies, the class's signing key in a table no student
// may read, and the functions through which a student opens, crashes, keeps
// the record of and submits an attempt (SECURITY DEFINER: the student has no right to write
// the attempts table itself). The store's schema name is spliced in where a
// function needs its search_path (@SCHEMA@, quoted).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace pupitre::store::class_pg {

// The group roles, made once per server (several classes and databases may
// share them): teachers read and write everything; each class is a group
// inside pupitre_students.
inline constexpr const char* kRoles = R"sql(
DO $$ BEGIN
    CREATE ROLE pupitre_teachers NOLOGIN;
EXCEPTION WHEN duplicate_object OR unique_violation THEN NULL;
END $$;
DO $$ BEGIN
    CREATE ROLE pupitre_students NOLOGIN;
EXCEPTION WHEN duplicate_object OR unique_violation THEN NULL;
END $$;
)sql";

// What each group may do, the server deciding (@SCHEMA@: the schema, quoted).
inline constexpr const char* kGrants = R"sql(
GRANT USAGE ON SCHEMA @SCHEMA@ TO pupitre_teachers, pupitre_students;
GRANT ALL ON ALL TABLES IN SCHEMA @SCHEMA@ TO pupitre_teachers;
GRANT USAGE, SELECT ON ALL SEQUENCES IN SCHEMA @SCHEMA@ TO pupitre_teachers, pupitre_students;

CREATE TABLE pupitre_class_key (
    id  integer PRIMARY KEY CHECK (id = 1),
    key text NOT NULL
);
INSERT INTO pupitre_class_key VALUES (1, encode(sha256(convert_to(
    gen_random_uuid()::text || gen_random_uuid()::text || gen_random_uuid()::text, 'UTF8')), 'hex'));
REVOKE ALL ON pupitre_class_key FROM PUBLIC, pupitre_students;
GRANT SELECT ON pupitre_class_key TO pupitre_teachers;

-- The class's texts: exercises and programs are read by all; programs are the
-- class's library, each revision signed by who wrote it.
GRANT SELECT ON pupitre_meta, exercises, exercise_texts, programs, revisions TO pupitre_students;
GRANT INSERT, UPDATE ON programs, revisions TO pupitre_students;
-- A student's own machines (LOGIN/NAME), their values, audit and workshop.
GRANT SELECT, INSERT, UPDATE, DELETE ON machines, correctors, origins, workshops TO pupitre_students;
GRANT SELECT, INSERT ON audit, imd_history TO pupitre_students;
GRANT SELECT, INSERT, UPDATE ON settings TO pupitre_students;
-- Attempts are read, never written, by a student: the functions below write.
GRANT SELECT ON attempts TO pupitre_students;

ALTER TABLE machines ENABLE ROW LEVEL SECURITY;
ALTER TABLE correctors ENABLE ROW LEVEL SECURITY;
ALTER TABLE origins ENABLE ROW LEVEL SECURITY;
ALTER TABLE workshops ENABLE ROW LEVEL SECURITY;
ALTER TABLE audit ENABLE ROW LEVEL SECURITY;
ALTER TABLE imd_history ENABLE ROW LEVEL SECURITY;
ALTER TABLE settings ENABLE ROW LEVEL SECURITY;
ALTER TABLE revisions ENABLE ROW LEVEL SECURITY;
ALTER TABLE attempts ENABLE ROW LEVEL SECURITY;

CREATE POLICY teachers ON machines TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON correctors TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON origins TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON workshops TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON audit TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON imd_history TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON settings TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON revisions TO pupitre_teachers USING (true) WITH CHECK (true);
CREATE POLICY teachers ON attempts TO pupitre_teachers USING (true) WITH CHECK (true);

CREATE POLICY own ON machines TO pupitre_students
    USING (starts_with(name, current_user || '/')) WITH CHECK (starts_with(name, current_user || '/'));
CREATE POLICY own ON correctors TO pupitre_students
    USING (starts_with(machine, current_user || '/'))
    WITH CHECK (starts_with(machine, current_user || '/'));
CREATE POLICY own ON origins TO pupitre_students
    USING (starts_with(machine, current_user || '/'))
    WITH CHECK (starts_with(machine, current_user || '/'));
CREATE POLICY own ON workshops TO pupitre_students
    USING (starts_with(machine, current_user || '/'))
    WITH CHECK (starts_with(machine, current_user || '/') AND who = current_user);
CREATE POLICY own ON audit TO pupitre_students
    USING (starts_with(machine, current_user || '/'))
    WITH CHECK (starts_with(machine, current_user || '/') AND who = current_user);
CREATE POLICY own ON imd_history TO pupitre_students
    USING (starts_with(machine, current_user || '/'))
    WITH CHECK (starts_with(machine, current_user || '/') AND who = current_user);
-- Settings: the console's own (its program, a program's lease) are shared;
-- the class's and the memory protection's are the teacher's.
CREATE POLICY consoles ON settings TO pupitre_students
    USING (true) WITH CHECK (key NOT LIKE 'class.%' AND key NOT LIKE 'protect.%');
CREATE POLICY read ON revisions FOR SELECT TO pupitre_students USING (true);
CREATE POLICY write ON revisions FOR INSERT TO pupitre_students WITH CHECK (who = current_user);
CREATE POLICY own ON attempts FOR SELECT TO pupitre_students USING (student = current_user);

-- An attempt opened: the student's open one at the exercise's current text,
-- else a new one with a seed drawn here, from the server's strong random
-- source, at every attempt. The opening is recorded with the server's time.
CREATE FUNCTION pupitre_open_attempt(p_exercise text, p_machine text) RETURNS SETOF attempts
LANGUAGE plpgsql SECURITY DEFINER SET search_path = @SCHEMA@, pg_temp AS $f$
DECLARE
    t text;
    sha text;
    a attempts;
BEGIN
    SELECT e.text INTO t FROM exercises e WHERE e.name = p_exercise;
    IF NOT FOUND THEN
        RAISE EXCEPTION 'no exercise named % on this server', p_exercise USING ERRCODE = 'P0002';
    END IF;
    sha := encode(sha256(convert_to(t, 'UTF8')), 'hex');
    SELECT * INTO a FROM attempts x WHERE x.exercise = p_exercise AND x.student = session_user
        AND x.submitted_ms IS NULL AND x.exercise_sha = sha ORDER BY x.id DESC LIMIT 1;
    IF FOUND THEN
        RETURN NEXT a;
        RETURN;
    END IF;
    IF NOT starts_with(p_machine, session_user || '/') THEN
        RAISE EXCEPTION 'the machine % is not %''s', p_machine, session_user
            USING ERRCODE = '42501';
    END IF;
    INSERT INTO attempts (exercise, exercise_sha, student, machine, started_ms, seed)
    VALUES (p_exercise, sha, session_user, p_machine,
            (extract(epoch FROM clock_timestamp()) * 1000)::bigint,
            left(encode(sha256(convert_to(gen_random_uuid()::text || gen_random_uuid()::text,
                                          'UTF8')), 'hex'), 16))
    RETURNING * INTO a;
    PERFORM pg_notify('pupitre_store', current_schema());  -- the teacher's watch hears it
    RETURN NEXT a;
END $f$;

CREATE FUNCTION pupitre_add_crash(p_id bigint) RETURNS void
LANGUAGE sql SECURITY DEFINER SET search_path = @SCHEMA@, pg_temp AS $f$
    UPDATE attempts SET crashes = crashes + 1
    WHERE id = p_id AND student = session_user AND submitted_ms IS NULL;
$f$;

-- :submit: the student's provisional result and record, at the server's
-- time; unsigned until the teacher's side grades it (pupitre class grade).
CREATE FUNCTION pupitre_submit(p_id bigint, p_score bigint, p_scrapped bigint, p_mistakes text,
                               p_found text, p_report text, p_record text) RETURNS bigint
LANGUAGE plpgsql SECURITY DEFINER SET search_path = @SCHEMA@, pg_temp AS $f$
DECLARE
    done bigint;
BEGIN
    UPDATE attempts SET submitted_ms = (extract(epoch FROM clock_timestamp()) * 1000)::bigint,
        seconds = ((extract(epoch FROM clock_timestamp()) * 1000)::bigint - started_ms) / 1000.0,
        score = p_score, scrapped = p_scrapped, mistakes = p_mistakes, found = p_found,
        report = p_report, record = p_record, signature = ''
    WHERE id = p_id AND student = session_user AND submitted_ms IS NULL
    RETURNING id INTO done;
    IF done IS NOT NULL THEN
        PERFORM pg_notify('pupitre_store', current_schema());
    END IF;
    RETURN done;
END $f$;

-- The record of an attempt in progress, kept as it grows (a console that
-- stops and starts again takes it up); the last action's time for the
-- teacher's view.
CREATE FUNCTION pupitre_keep_record(p_id bigint, p_record text) RETURNS void
LANGUAGE plpgsql SECURITY DEFINER SET search_path = @SCHEMA@, pg_temp AS $f$
BEGIN
    UPDATE attempts SET record = p_record
    WHERE id = p_id AND student = session_user AND submitted_ms IS NULL;
    IF FOUND THEN
        PERFORM pg_notify('pupitre_class', 'action ' || p_id);
    END IF;
END $f$;

REVOKE ALL ON FUNCTION pupitre_open_attempt(text, text), pupitre_add_crash(bigint),
    pupitre_submit(bigint, bigint, bigint, text, text, text, text),
    pupitre_keep_record(bigint, text) FROM PUBLIC;
GRANT EXECUTE ON FUNCTION pupitre_open_attempt(text, text), pupitre_add_crash(bigint),
    pupitre_submit(bigint, bigint, bigint, text, text, text, text),
    pupitre_keep_record(bigint, text) TO pupitre_students, pupitre_teachers;
)sql";

}  // namespace pupitre::store::class_pg
