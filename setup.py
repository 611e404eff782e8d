"""Build hook of the optional compiled kernel; the project is described in pyproject.toml.

``ballrace.analytic._ldkernel`` (analytic/_ldkernel.c, the one-load-case Newton iteration
of the static load distribution) is built where a C compiler and the Python headers exist.
It is optional: without them the install goes on and loaddist runs the same iteration in
NumPy (the same answers, about 5 times slower for one load case; docs/performance.md).

The package-dir mapping ("ballrace" = the repository root) would ship this script as
``ballrace.setup``; the build_py below leaves it out.
"""
if __name__ == "__main__":
    from setuptools import Extension, setup
    from setuptools.command.build_py import build_py

    class BuildPy(build_py):
        def find_package_modules(self, package, package_dir):
            return [m for m in super().find_package_modules(package, package_dir)
                    if not (package == "ballrace" and m[1] == "setup")]

    setup(ext_modules=[Extension("ballrace.analytic._ldkernel", ["analytic/_ldkernel.c"],
                                 optional=True)],
          cmdclass={"build_py": BuildPy})
