"""nbgrader's configuration for this repository as a course: `nbgrader generate_assignment lessons`
(run from here) takes source/lessons/ as the assignment and writes release/lessons/.

The stubs are nbgrader's defaults, written out because `python -m interp.editions student`
uses the same code stub: both make the same exercise cells.
"""

c = get_config()  # noqa: F821 (nbgrader provides it)
c.CourseDirectory.course_id = "interp"
c.ClearSolutions.code_stub = {"python": "# YOUR CODE HERE\nraise NotImplementedError()"}
c.ClearSolutions.text_stub = "YOUR ANSWER HERE"
