# ctest packaging.version: the installed pita --version prints "pita <the
# project's version>" (CMakeLists.txt, the one place the version is set).
execute_process(COMMAND "${PITA}" --version OUTPUT_VARIABLE out RESULT_VARIABLE result OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT result EQUAL 0 OR NOT out STREQUAL "${EXPECTED}")
  message(FATAL_ERROR "${PITA} --version: exit ${result}, printed \"${out}\", expected \"${EXPECTED}\"")
endif()
