"""Case-file readers (boundary code): TOML files with unit strings, parsed with pint and
validated here, handed on as SI floats.

:mod:`ballrace.casefiles.bearing` reads bearing case files and holds the helpers the shaft
and FE case files share (quantities, speeds, temperatures, key checks).  Every reading
error is a :class:`ballrace.errors.CaseFileError` naming the file and the key.
"""
