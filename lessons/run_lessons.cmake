# Runs every lesson in order with its default options (the `lessons` target):
#   cmake -DBIN=<bin dir> -DOUT=<out dir> -DLESSONS=01_rays,02_recursive,... [-DSUFFIX=.exe]
#         [-DEMULATOR=qemu-aarch64|-L|/usr/aarch64-linux-gnu] -P run_lessons.cmake
# (a cross build runs them through its emulator).
# A lesson that stops at an exercise still to be written (exit status 3, in a student
# kit) does not stop the others: they are all run, and a summary says which wait for
# which exercise. Any other failure fails the target, after the rest have run.
string(REPLACE "," ";" LESSONS "${LESSONS}")
string(REPLACE "|" ";" EMULATOR "${EMULATOR}")
set(waiting "")
set(failed "")
foreach(name IN LISTS LESSONS)
  message("== ${name} ==")
  execute_process(COMMAND ${EMULATOR} ${BIN}/${name}${SUFFIX} --out ${OUT}/${name} RESULT_VARIABLE status)
  if(status EQUAL 3)
    list(APPEND waiting ${name})
  elseif(NOT status EQUAL 0)
    list(APPEND failed "${name} (${status})")
  endif()
endforeach()
if(waiting)
  list(JOIN waiting ", " names)
  message("lessons waiting for an exercise (see the lines above): ${names}")
endif()
if(failed)
  list(JOIN failed ", " names)
  message(FATAL_ERROR "lessons that failed: ${names}")
endif()
