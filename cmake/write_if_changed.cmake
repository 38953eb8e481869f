# Writes `content` to `file` only when it differs from what is there, so a re-configure or a
# build step that generates the same text leaves the file's time alone and rebuilds nothing.
function(lt_write_if_changed file content)
  set(old "")
  if(EXISTS ${file})
    file(READ ${file} old)
  endif()
  if(NOT "${old}" STREQUAL "${content}")
    file(WRITE ${file} "${content}")
  endif()
endfunction()
