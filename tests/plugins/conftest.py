"""The directories ``*_dist`` hold test distributions of broken plugins, found through their ``.dist-info``
when a test puts them on sys.path; their modules must not be imported by collection (one calls sys.exit)."""

collect_ignore_glob = ["*_dist"]
