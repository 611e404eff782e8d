"""Case-file readers (boundary code): TOML files with unit strings, parsed with pint and
validated here, handed on as SI floats.

:mod:`ballrace.casefiles.bearing` reads bearing case files (and holds the helpers every
reader uses: quantities, speeds, temperatures, key checks), :mod:`ballrace.casefiles.shaft`
shaft case files; :mod:`ballrace.casefiles.schema` defines the sections they and the FE
case file share; :mod:`ballrace.casefiles.analysis` runs a bearing case.  Every reading
error is a :class:`ballrace.errors.CaseFileError` naming the file and the key.
"""
