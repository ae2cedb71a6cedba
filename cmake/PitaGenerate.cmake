# Run by src/CMakeLists.txt each time pita is linked (cmake -P): writes the man
# page and the shell completions that `pita --generate` prints from the
# command-line definitions of --help, into OUT_DIR/pita.1,
# OUT_DIR/completions/pita (bash) and OUT_DIR/completions/_pita (zsh).
# Each file is written to a temporary name and renamed into place.
foreach(var PITA OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "PitaGenerate.cmake: -D${var}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT_DIR}/completions")
foreach(pair "man;pita.1" "bash;completions/pita" "zsh;completions/_pita")
  list(GET pair 0 what)
  list(GET pair 1 name)
  execute_process(COMMAND "${PITA}" --generate ${what}
                  OUTPUT_FILE "${OUT_DIR}/${name}.tmp"
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${PITA} --generate ${what} failed (${result})")
  endif()
  file(RENAME "${OUT_DIR}/${name}.tmp" "${OUT_DIR}/${name}")
endforeach()
