# interplay-sweep end to end (ctest test_sweep_cli): the same grid run in-process with --jobs 2,
# and from --emit-jobs through GNU parallel (also with --sshlogin), xargs -P and, where a Slurm
# controller answers, a Slurm job array, and merged, gives the same knobs and error values bit for
# bit (timings and the fronts they decide are excluded); resuming runs only what is missing; each
# bad input gets its exit code and message and leaves nothing written.
# cmake -DSWEEP=path/to/interplay-sweep -DWORK=scratch/dir -P test_sweep_cli.cmake

cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# The projectile of test_sweep: a ball thrown with nothing to hit, 0.5 s.
set(scene "${WORK}/projectile.json")
file(WRITE "${scene}" [[{
  "format": "interplay.scene", "version": 1,
  "settings": { "gravity": [0, -9.81, 0], "damping": { "linear": 0, "angular": 0 }, "sleep": { "enabled": false } },
  "bodies": [ { "name": "ball", "shape": { "type": "box", "halfExtents": [0.1, 0.2, 0.3] }, "mass": 1,
                "linearVelocity": [3, 5, 0], "angularVelocity": [1, 2, 3] } ]
}]])
set(grid --knob timeStep=0.016666668,0.008333334 --knob substeps=1,2,4 --seconds 0.5
         --reference timeStep=0.004166667 --reference substeps=4)

function(expect_run code pattern)  # expect_run(CODE REGEX ARGS...): exit code and a line of stderr
    execute_process(COMMAND "${SWEEP}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL code)
        message(FATAL_ERROR "interplay-sweep ${ARGN}: exit ${rc}, expected ${code}\n${out}\n${err}")
    endif()
    if(NOT "${out}${err}" MATCHES "${pattern}")
        message(FATAL_ERROR "interplay-sweep ${ARGN}: output does not match '${pattern}':\n${out}\n${err}")
    endif()
    set(last_output "${out}" PARENT_SCOPE)
endfunction()

# The comparable part of a sweep.json: every point's knobs and measures, in grid order.
function(sweep_values dir result)
    file(READ "${dir}/sweep.json" json)
    string(JSON count LENGTH "${json}" points)
    if(count EQUAL 0)
        message(FATAL_ERROR "${dir}/sweep.json has no points")
    endif()
    math(EXPR last "${count} - 1")
    set(values "")
    foreach(i RANGE ${last})
        string(JSON knobs GET "${json}" points ${i} knobs)
        string(JSON measures GET "${json}" points ${i} measures)
        string(APPEND values "${knobs} ${measures}\n")
    endforeach()
    string(JSON reference GET "${json}" reference convergence)
    set(${result} "${values}reference ${reference}" PARENT_SCOPE)
endfunction()

# --- bad input: exit code, message, and no output directory created ---
expect_run(2 "unknown setting 'solver.bogus'" "${scene}" --knob solver.bogus=1,2 --out "${WORK}/bad")
expect_run(2 "the grid is empty: --knob substeps has no values" "${scene}" --knob substeps= --out "${WORK}/bad")
expect_run(2 "knob 'substeps=0': invalid value for setting 'substeps'" "${scene}" --knob substeps=1,0 --out "${WORK}/bad")
expect_run(2 "unknown option '--bogus'" "${scene}" --bogus 1)
expect_run(2 "--target expects MEASURE=LIMIT" "${scene}" --target depth=1)
file(WRITE "${WORK}/empty-grid.json" [[{"knobs": {"substeps": []}}]])
expect_run(2 "the grid is empty: knob 'substeps' has no values" "${scene}" --grid "${WORK}/empty-grid.json" --out "${WORK}/bad")
expect_run(3 "cannot open the scene" "${WORK}/no-such-scene.json" --out "${WORK}/bad")
file(WRITE "${WORK}/broken.json" [[{"format": "interplay.scene", "version": 1, "bodies": [ {"shape": 5} ]}]])
expect_run(3 "broken.json: error at /bodies/0/shape" "${WORK}/broken.json" --out "${WORK}/bad")
if(EXISTS "${WORK}/bad")
    message(FATAL_ERROR "a refused sweep created its --out directory")
endif()

# --- a --grid file, with a --knob on top: 2 x 2 points of 0.25 s ---
file(WRITE "${WORK}/grid.json" [[{"knobs": {"substeps": [1, 2]}, "seconds": 0.25, "reference": {"substeps": 4}}]])
expect_run(0 "for deepest penetration" "${scene}" --grid "${WORK}/grid.json" --knob solver.velocityIterations=1,2
           --out "${WORK}/gridfile")
file(READ "${WORK}/gridfile/sweep.json" grid_json)
string(JSON grid_points LENGTH "${grid_json}" points)
string(JSON grid_seconds GET "${grid_json}" seconds)
string(JSON grid_last GET "${grid_json}" points 3 knobs)
if(NOT grid_points EQUAL 4 OR NOT grid_seconds EQUAL 0.25 OR NOT grid_last MATCHES "substeps=2.*solver.velocityIterations=2")
    message(FATAL_ERROR "--grid was not followed: ${grid_points} points, ${grid_seconds} s, last ${grid_last}")
endif()

# --- in process, two threads ---
expect_run(0 "for deepest penetration <= 0.001 m: timeStep=1/[0-9]+ s, substeps=[0-9] — .* ms/step"
           "${scene}" ${grid} --jobs 2 --out "${WORK}/threads")
expect_run(0 "2 points at a time" --merge "${WORK}/threads")  # a --jobs directory merges too
file(READ "${WORK}/threads/sweep.json" threads_json)
if(NOT threads_json MATCHES "noisier than --jobs 1")
    message(FATAL_ERROR "sweep.json does not say that --jobs 2 timings are noisier")
endif()
foreach(f sweep.csv sweep-positionMax.svg sweep-penetration.svg sweep-jointError.svg)
    if(NOT EXISTS "${WORK}/threads/${f}")
        message(FATAL_ERROR "no ${f} in ${WORK}/threads")
    endif()
endforeach()
sweep_values("${WORK}/threads" expected)

# --- emitted jobs through GNU parallel (here and through --sshlogin), xargs -P and a Slurm job
# array, then merged ---
# --sshlogin without an ssh server: this stand-in does what sshd does on the host, running the
# command line parallel sends (its arguments after the host and "--", joined) through a shell, so
# parallel's remote path (the quoting for the remote shell, --workdir, the host's job slots) runs.
# sshd sets SHELL from the account's login shell, and parallel's remote wrapper runs the job
# through $SHELL: where the test's own environment has none (CI), the job silently did not run.
set(fake_ssh "${WORK}/fake-ssh")
file(WRITE "${fake_ssh}" "#!/bin/sh\nshift\n[ \"$1\" = \"--\" ] && shift\nSHELL=/bin/sh exec sh -c \"$*\"\n")
file(CHMOD "${fake_ssh}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
# Slurm runs only where a controller answers (docs/sweep.md says how it was tested); CI has none.
set(runners parallel sshlogin xargs)
find_program(SBATCH sbatch)
if(SBATCH)
    execute_process(COMMAND sinfo -h -o %a TIMEOUT 10 RESULT_VARIABLE sinfo_rc OUTPUT_VARIABLE sinfo_out ERROR_QUIET)
endif()
if(SBATCH AND sinfo_rc EQUAL 0 AND sinfo_out MATCHES "up")
    list(APPEND runners slurm)
else()
    message(STATUS "SKIPPED: the Slurm job array recipe (no sbatch, or no Slurm controller answers sinfo)")
endif()
foreach(runner ${runners})
    set(dir "${WORK}/${runner}")
    set(jobs "${WORK}/${runner}-jobs.txt")
    expect_run(0 "wrote 6 commands" "${scene}" ${grid} --out "${dir}" --emit-jobs "${jobs}")
    expect_run(6 "6 of 6 points have no result" --merge "${dir}")
    if(runner STREQUAL "parallel")
        set(command parallel --will-cite --jobs 2)
    elseif(runner STREQUAL "sshlogin")
        set(command parallel --will-cite --ssh "${fake_ssh}" --sshlogin 2/node1 --jobs 1 --workdir .)
    elseif(runner STREQUAL "xargs")
        set(command xargs -d "\\n" -P 2 -n 1 sh -c)
    else()
        # docs/sweep.md's recipe, with --wait on the merge job that depends on the array.
        execute_process(COMMAND sbatch --parsable --array=1-6%2 --cpus-per-task=1 -o /dev/null
                                --wrap "sh -c \"$(sed -n \${SLURM_ARRAY_TASK_ID}p '${jobs}')\""
                        RESULT_VARIABLE rc OUTPUT_VARIABLE array ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
        if(NOT rc EQUAL 0)
            message(FATAL_ERROR "sbatch --array over the emitted jobs: exit ${rc}\n${err}")
        endif()
        set(command sbatch --wait --dependency=afterok:${array} -o /dev/null --wrap "'${SWEEP}' --merge '${dir}'")
    endif()
    execute_process(COMMAND ${command} INPUT_FILE "${jobs}" RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${runner} over the emitted jobs: exit ${rc}\n${err}")
    endif()
    if(NOT runner STREQUAL "slurm")  # the Slurm recipe merged in its own job
        expect_run(0 "for deepest penetration" --merge "${dir}")
    endif()
    sweep_values("${dir}" got)
    if(NOT got STREQUAL expected)
        message(FATAL_ERROR "${runner}'s merged result differs from --jobs 2:\n${got}\n---\n${expected}")
    endif()
endforeach()

# --- merge refuses a corrupt or foreign point, and writes nothing then ---
file(GLOB points "${WORK}/parallel/points/*.json")
list(GET points 0 victim)
file(READ "${WORK}/parallel/sweep.json" before)
file(READ "${victim}" victim_text)
string(SUBSTRING "${victim_text}" 0 40 truncated)
file(WRITE "${victim}" "${truncated}")
get_filename_component(victim_name "${victim}" NAME)
expect_run(5 "${victim_name}: corrupt" --merge "${WORK}/parallel")
string(REPLACE "\"sweep\": \"" "\"sweep\": \"0" foreign "${victim_text}")
file(WRITE "${victim}" "${foreign}")
expect_run(5 "${victim_name}: belongs to another sweep" --merge "${WORK}/parallel")
file(READ "${WORK}/parallel/sweep.json" after)
if(NOT before STREQUAL after)
    message(FATAL_ERROR "a refused merge changed sweep.json")
endif()

# --- resuming: only the missing point runs again ---
file(GLOB points "${WORK}/threads/points/*.json")
list(GET points 0 removed)
list(GET points 1 kept)
file(READ "${kept}" kept_before)
file(REMOVE "${removed}")
expect_run(0 "for deepest penetration" "${scene}" ${grid} --out "${WORK}/threads")
if(NOT EXISTS "${removed}")
    message(FATAL_ERROR "resuming did not run the missing point")
endif()
file(READ "${kept}" kept_after)
if(NOT kept_before STREQUAL kept_after)
    message(FATAL_ERROR "resuming ran a point whose result was on disk")
endif()
# Another sweep (a different duration) in the same directory is refused, not mixed in.
expect_run(2 "holds the results of another sweep" "${scene}" --knob substeps=1 --seconds 0.25 --out "${WORK}/threads")
expect_run(2 "holds the results of another sweep" "${scene}" --point substeps=1 --seconds 0.25 --out "${WORK}/xargs")
file(GLOB leftovers "${WORK}/threads/.*" "${WORK}/threads/points/.*")
if(leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
