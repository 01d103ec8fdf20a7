# The diagnostics of one testdata file with sfcheck given the flags in
# NAME.flags beside it: the limits are reached only by lowering them, so
# their files carry the flags that do. The comparison is the corpus's own.
# Called as: cmake -DSFCHECK=... -DDIR=... -DNAME=... -DCHECK_SCRIPT=... -P this
file(READ ${DIR}/${NAME}.flags flags)
string(STRIP "${flags}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
set(SFCHECK ${SFCHECK} ${flags})
include(${CHECK_SCRIPT})
