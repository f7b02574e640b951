# Runs a replay target whose inputs go through the private folder (private_folder.h), with TMPDIR set to an empty
# folder of its own, and fails if anything is left in that folder when the target has exited.
#   cmake -DREPLAY=<replay_target> -DINPUTS=<folder> -DFOLDER=<scratch folder> -P private_folder_removed.cmake
file(REMOVE_RECURSE ${FOLDER})
file(MAKE_DIRECTORY ${FOLDER})
execute_process(COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${FOLDER} ${REPLAY} ${INPUTS} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${REPLAY} failed: ${status}")
endif()
file(GLOB left ${FOLDER}/*)
if(left)
  message(FATAL_ERROR "the private folder was left behind: ${left}")
endif()
