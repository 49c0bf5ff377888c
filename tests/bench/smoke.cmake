# Runs radiant-bench on one validation scene, the smallest office (with a coarse reference) and a
# scene file (against the RADIANCE reference beside it) with three methods; fails unless it exits
# 0, prints the table with a row per case, reports the time to error, and writes the Markdown,
# CSV and (with gnuplot) PNG files.
# A scene file without sensors must be refused with exit code 2; the smallest office is scored
# against traced paths with --reference paths. With --peer radiance the bench
# either notes that RADIANCE is not on PATH or adds the peer's table and the speed at equal
# error; --radiance-reference either fails with that note or writes a reference CSV.
foreach(ext md csv gp png)
  file(REMOVE ${OUT}.${ext})
endforeach()
execute_process(COMMAND ${BENCH} --scenes parallel-squares-d1,office-x1,${DATA}/radiance/room-s2.json
                        --methods direct,hierarchical,monte-carlo --tolerance 0.3
                        --reference-tolerance 0.1 --max-seconds 20 --out ${OUT} --cache ${CACHE}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "radiant-bench exited with ${rc}")
endif()
string(FIND "${out}" "| scene | triangles | method | tolerance | seconds | rays | elements | links | peak MiB | rms error | max error | error estimate | estimate / rms | status | stages (s) | estimate parts |" header)
if(header EQUAL -1)
  message(FATAL_ERROR "the table header was not printed")
endif()
foreach(row "| parallel-squares-d1 | 4 | direct | 0.3 |" "| office-x1 | 500 | hierarchical | 0.3 |"
            "| room-s2 | 20 | hierarchical | 0.3 |" "| room-s2 | 20 | monte-carlo | 0.3 |"
            "photons"
            "Time to an RMS error of at most 0.02")
  string(FIND "${out}" "${row}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "missing from the output: ${row}")
  endif()
endforeach()
string(FIND "${err}" "reference of room-s2: RADIANCE (room-s2.reference.csv)" found)
if(found EQUAL -1)
  message(FATAL_ERROR "the scene file was not scored against the reference beside it")
endif()
set(files ${OUT}.md ${OUT}.csv)
if(GNUPLOT)
  list(APPEND files ${OUT}.png)
endif()
foreach(f ${files})
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "radiant-bench did not write ${f}")
  endif()
endforeach()

execute_process(COMMAND ${BENCH} --scenes ${DATA}/scenes/parallel-squares-d1.json --out ${OUT}-refused
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${err}" "has no sensors" said)
if(NOT rc EQUAL 2 OR said EQUAL -1)
  message(FATAL_ERROR "a scene file without sensors was not refused (${rc}): ${out}${err}")
endif()

# The smallest office against traced paths (--reference paths), cached like the solves.
execute_process(COMMAND ${BENCH} --scenes office-x1 --methods monte-carlo --tolerance 0.3
                        --reference paths --path-error 0.05 --out ${OUT}-paths --cache ${CACHE}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${err}" "reference of office-x1: traced paths" traced)
string(FIND "${out}" "| office-x1 | 500 | monte-carlo | 0.3 |" row)
if(NOT rc EQUAL 0 OR traced EQUAL -1 OR row EQUAL -1)
  message(FATAL_ERROR "--reference paths (${rc}): ${out}${err}")
endif()

execute_process(COMMAND ${BENCH} --scenes parallel-squares-d1,room-s2 --methods direct
                        --tolerance 0.3 --max-seconds 20 --peer radiance
                        --radiance-settings "-ab 1 -aa 0 -ad 32" --out ${OUT}-peer
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "radiant-bench --peer radiance exited with ${rc}")
endif()
string(FIND "${out}" "RADIANCE (oconv and rtrace) is not on PATH" missing)
if(missing EQUAL -1)
  foreach(row "| room-s2 | -ab 1 -aa 0 -ad 32 |" "| parallel-squares-d1 | -ab 1 -aa 0 -ad 32 |"
              "| room-s2 | 20 | radiance |" "Speed at equal error")
    string(FIND "${out}" "${row}" found)
    if(found EQUAL -1)
      message(FATAL_ERROR "missing from the peer's output: ${row}")
    endif()
  endforeach()
endif()

file(REMOVE ${OUT}-reference.csv)
execute_process(COMMAND ${BENCH} --radiance-reference ${DATA}/radiance/room-s2.json
                        --radiance-runs 2 --radiance-reference-settings "-ab 1 -aa 0 -ad 32"
                        --out ${OUT}-reference.csv
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(missing EQUAL -1)
  file(STRINGS ${OUT}-reference.csv lines)
  list(LENGTH lines n)
  list(GET lines 0 header)
  string(FIND "${out}" "standard error: RMS" noise)
  if(NOT rc EQUAL 0 OR NOT n EQUAL 82 OR noise EQUAL -1
     OR NOT header STREQUAL "x,y,z,irradiance,standard_error")
    message(FATAL_ERROR "no RADIANCE reference (${rc}, ${n} lines): ${out}${err}")
  endif()
else()
  string(FIND "${err}" "not on PATH" said)
  if(NOT rc EQUAL 1 OR said EQUAL -1)
    message(FATAL_ERROR "--radiance-reference without RADIANCE: ${rc}: ${out}${err}")
  endif()
endif()
