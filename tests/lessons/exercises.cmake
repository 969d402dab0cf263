# The pages' exercises that run the course's binaries with other options, performed as their text
# says, each target checked both as the page states it and as the run prints or draws it
# (tests/lessons/run_exercise.sh; exercises 14.2, 18.2, 18.4 and 19.2 have their own scripts, beside
# their chapters' tests); and two of the pages' tables, measured again the same way: docs/03's "How
# close to forward" and docs/06's "How exact is RGBA16F?" (03.exactness, 06.exactness).
# NN.K is pages.NN_exercise_K; NN.NAME is pages.NN_NAME.
function(course_page_exercises)
  foreach(exercise ${ARGN})
    if(exercise MATCHES "^[0-9]+\\.[0-9]+$")
      string(REPLACE "." "_exercise_" name ${exercise})
    else()
      string(REPLACE "." "_" name ${exercise})
    endif()
    add_test(NAME pages.${name}
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/lessons/run_exercise.sh $<TARGET_FILE_DIR:00_forward>
              ${CMAKE_SOURCE_DIR} ${COURSE_TEST_OUT}/${name} ${exercise})
    set_tests_properties(pages.${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endforeach()
endfunction()
if(TARGET 00_forward AND TARGET imgdiff)
  course_page_exercises(00.2 00.3 01.2 02.3 02.4 02.5 03.3 04.1 05.1 05.2 05.3 06.2 07.2 07.3 08.4 10.5 10.6 11.1
                        12.5 13.3 13.4 13.6 14.3 14.4 16.3 16.4 16.6 16.7 17.5 03.exactness 06.exactness)
endif()
