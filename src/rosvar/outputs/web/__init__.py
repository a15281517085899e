"""``rosvar serve``: the step-by-step configuration as an offline single-page web app.

``server`` speaks HTTP (the app's own files and the JSON API, nothing else), ``api`` turns
validated requests into engine calls, ``sessions`` keeps one configuration session per
browser tab, ``assets`` holds the app (``static/``: HTML, CSS, plain JavaScript and the
vendored libraries with their licences).
"""
