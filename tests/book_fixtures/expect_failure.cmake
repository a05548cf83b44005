# Runs the book builder on a fixture that must be rejected, and passes only when
# the builder exits with status 1 AND names the expected problem: a crash or a
# failure for some other reason does not count as the check working.
#
#   cmake -DPYTHON=... -DBUILDER=... -DROOT=... -DEXPECT=<regex> -P expect_failure.cmake
foreach(var PYTHON BUILDER ROOT EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_failure.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(
  COMMAND ${PYTHON} ${BUILDER} --check --root ${ROOT}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message("${out}${err}")

if(NOT status EQUAL 1)
  message(FATAL_ERROR "expected exit status 1 from the book builder, got '${status}'")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "the builder failed, but its messages do not match '${EXPECT}'")
endif()
message("the builder rejected ${ROOT} as expected")
