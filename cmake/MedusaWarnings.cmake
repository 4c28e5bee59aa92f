# Warning flags for medusa's own targets. Third-party headers come in as SYSTEM, so their warnings
# do not count.
function(medusa_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(MEDUSA_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

if(MEDUSA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
