#version 3.7;
// a line comment
/* a block
   comment */
#debug "after comments\n"
/* nested /* block */ comment */
#debug "after nested comment\n"
