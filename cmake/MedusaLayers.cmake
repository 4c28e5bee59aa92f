# The libraries' dependency order (docs/CONVENTIONS.md): core <- kinetic <- medusa <- persistence <-
# pipeline (io, cli). A library may link only libraries before it; configuration stops otherwise, so
# a link that would let libkinetic see the store, or libmedusa see PHAT's users, never builds.
# tests/check_include_layers.py checks the same order on the #include lines.

# medusa_check_layers(<target>...): the targets in dependency order, earliest first.
function(medusa_check_layers)
  set(order ${ARGN})
  string(REPLACE ";" " <- " shown "${order}")
  list(LENGTH order count)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    list(GET order ${i} target)
    get_target_property(type ${target} TYPE)
    set(links "")
    foreach(property INTERFACE_LINK_LIBRARIES LINK_LIBRARIES)
      if(type STREQUAL "INTERFACE_LIBRARY" AND property STREQUAL "LINK_LIBRARIES")
        continue()
      endif()
      get_target_property(values ${target} ${property})
      if(values)
        list(APPEND links ${values})
      endif()
    endforeach()
    foreach(link IN LISTS links)
      # $<LINK_ONLY:x> (a static library's private dependency) names x too.
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      if(NOT TARGET "${link}")
        continue()
      endif()
      get_target_property(aliased "${link}" ALIASED_TARGET)
      if(aliased)
        set(link ${aliased})
      endif()
      list(FIND order "${link}" j)
      if(j GREATER_EQUAL i)
        message(FATAL_ERROR "${target} links ${link}, which comes after it in the dependency order "
                            "${shown} (docs/CONVENTIONS.md): a library may use only those before it")
      endif()
    endforeach()
  endforeach()
endfunction()
