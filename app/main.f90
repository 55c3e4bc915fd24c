program fricon
    implicit none
    print '(a)', 'fricon: under construction'
end program fricon
