# tests/harness/list_views.cmake — writes OUT: every lab's views as its built
# headless program lists them (--list-views), one line per view,
# "<lab> <view>[ expect_error][ same_as=<other>]", or "<lab> LIST_VIEWS_FAILED"
# when the program cannot list them. Run by the build (tests/CMakeLists.txt)
# after the labs link, so that programs_test reads the views from one file
# instead of starting every lab's program in each of its processes.
#   cmake -DBIN_DIR=build/bin -DLABS=01_immediate_mode,02_display_lists -DOUT=views.txt -P list_views.cmake
string(REPLACE "," ";" labs "${LABS}")
set(text "")
foreach(lab IN LISTS labs)
  execute_process(COMMAND ${BIN_DIR}/${lab} --list-views
                  OUTPUT_VARIABLE views RESULT_VARIABLE status ERROR_QUIET)
  if(NOT status EQUAL 0)
    string(APPEND text "${lab} LIST_VIEWS_FAILED\n")
    continue()
  endif()
  string(REGEX REPLACE "\n$" "" views "${views}")
  string(REPLACE "\n" ";" views "${views}")
  foreach(view IN LISTS views)
    string(APPEND text "${lab} ${view}\n")
  endforeach()
endforeach()
# Written whole, then renamed: a test never reads half a file.
file(WRITE ${OUT}.tmp "${text}")
file(RENAME ${OUT}.tmp ${OUT})
