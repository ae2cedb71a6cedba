// References to sections in words (tests/docs/self_test.py): this one resolves
// (docs/page.md "A heading"), this one does not (docs/page.md "No such section"),
// and neither does a page that is missing (docs/gone.md "A heading").
