// Parentheses nested past the reader's limit are refused.
#declare X = ((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((1))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))));
camera { location <0, 1, -5> look_at 0 }
